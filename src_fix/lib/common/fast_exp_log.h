// SPDX-License-Identifier: GPL-2.0-or-later
// Natural logarithm and exponential for the per-contact hot loops (plain C++).
//
// The lubricated contact takes three logarithms and two exponentials per contact and step
// (the Hamrock-Dowson powers, the gap integral). glibc's log and exp are out-of-line calls of
// ~50 instructions each, with their errno wrappers; these inline ones are ~25 and agree with
// them to a few ulp (tests/lib/common/test_fast_exp_log.cpp checks 1e6 arguments each).
// Arguments outside the ranges below go to std::log / std::exp.
#ifndef OHMDEM_FAST_EXP_LOG_H
#define OHMDEM_FAST_EXP_LOG_H

#include <cmath>
#include <cstdint>
#include <cstring>

namespace ohmdem {

// ln 2 split so that k * kLn2Hi is exact for |k| < 2^11 (fdlibm's constants).
constexpr double kLn2Hi = 6.93147180369123816490e-01;
constexpr double kLn2Lo = 1.90821492927058770002e-10;

inline double log_fast(double x)
{
  if (!(x >= 2.3e-308 && x <= 1.7e308)) return std::log(x);  // zero, negative, subnormal, inf, NaN
  // x = 2^k m with m in [sqrt(1/2), sqrt(2)) (musl's offset trick on the bits).
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::int64_t k = static_cast<std::int64_t>(bits - 0x3fe6a09e667f3bcdull) >> 52;
  bits -= static_cast<std::uint64_t>(k) << 52;
  double m;
  std::memcpy(&m, &bits, sizeof m);
  // ln m = 2 atanh(s), s = (m - 1)/(m + 1), |s| <= 0.1716: the odd series to s^19 leaves
  // s^20/21 < 3e-17 relative.
  const double f = m - 1.0, s = f / (m + 1.0), z = s * s;
  const double p =
      1.0 / 3 +
      z * (1.0 / 5 +
           z * (1.0 / 7 +
                z * (1.0 / 9 +
                     z * (1.0 / 11 +
                          z * (1.0 / 13 + z * (1.0 / 15 + z * (1.0 / 17 + z * (1.0 / 19))))))));
  // 2 s = f - s f: the leading term without the rounding of 2 s.
  const double kd = static_cast<double>(k);
  return kd * kLn2Hi + ((f - s * f) + (2.0 * s * z * p + kd * kLn2Lo));
}

inline double exp_fast(double x)
{
  if (!(x > -708.0 && x < 709.0)) return std::exp(x);  // overflow, subnormal results, NaN
  // x = k ln 2 + r, |r| <= ln2/2 (k rounded to nearest by the 1.5 * 2^52 shift).
  constexpr double kShift = 6755399441055744.0, kInvLn2 = 1.4426950408889634;
  const double kd = (x * kInvLn2 + kShift) - kShift;
  const double r = (x - kd * kLn2Hi) - kd * kLn2Lo;
  // Taylor to r^13: r^14/14! < 5e-18.
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = 1.0 / 479001600.0 + r * p;
  p = 1.0 / 39916800.0 + r * p;
  p = 1.0 / 3628800.0 + r * p;
  p = 1.0 / 362880.0 + r * p;
  p = 1.0 / 40320.0 + r * p;
  p = 1.0 / 5040.0 + r * p;
  p = 1.0 / 720.0 + r * p;
  p = 1.0 / 120.0 + r * p;
  p = 1.0 / 24.0 + r * p;
  p = 1.0 / 6.0 + r * p;
  p = 0.5 + r * p;
  const double e = 1.0 + (r + r * r * p);
  // Times 2^k through the exponent bits (k in [-1022, 1023] keeps e 2^k normal for
  // e in [0.7, 1.5] except at the two ends, which the range check excludes).
  std::uint64_t bits;
  std::memcpy(&bits, &e, sizeof bits);
  bits += static_cast<std::uint64_t>(static_cast<std::int64_t>(kd)) << 52;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  return y;
}

}  // namespace ohmdem

#endif
