// SPDX-License-Identifier: GPL-2.0-or-later
// Natural logarithm and exponential for the per-contact hot loops (plain C++).
//
// The lubricated contact takes three logarithms and two exponentials per contact and step
// (the Hamrock-Dowson powers, the gap integral). glibc's log and exp are out-of-line calls of
// ~50 instructions each, with their errno wrappers; these inline ones are ~30, table-driven
// like glibc's (32 entries each), and agree with glibc to a few ulp
// (tests/lib/common/test_fast_exp_log.cpp checks 1e6 arguments each). Arguments outside the
// ranges below go to std::log / std::exp.
#ifndef OHMDEM_FAST_EXP_LOG_H
#define OHMDEM_FAST_EXP_LOG_H

#include <cmath>
#include <cstdint>
#include <cstring>

namespace ohmdem {

namespace fast_exp_log_detail {
// ln 2 split so that k * kLn2Hi is exact for |k| < 2^21 (fdlibm's constants).
constexpr double kLn2Hi = 6.93147180369123816490e-01;
constexpr double kLn2Lo = 1.90821492927058770002e-10;
// 2^(j/32), j = 0..31, correctly rounded (computed with 60-digit decimal arithmetic).
inline constexpr double kExp2[32] = {
    0x1.0000000000000p+0, 0x1.059b0d3158574p+0, 0x1.0b5586cf9890fp+0, 0x1.11301d0125b51p+0,
    0x1.172b83c7d517bp+0, 0x1.1d4873168b9aap+0, 0x1.2387a6e756238p+0, 0x1.29e9df51fdee1p+0,
    0x1.306fe0a31b715p+0, 0x1.371a7373aa9cbp+0, 0x1.3dea64c123422p+0, 0x1.44e086061892dp+0,
    0x1.4bfdad5362a27p+0, 0x1.5342b569d4f82p+0, 0x1.5ab07dd485429p+0, 0x1.6247eb03a5585p+0,
    0x1.6a09e667f3bcdp+0, 0x1.71f75e8ec5f74p+0, 0x1.7a11473eb0187p+0, 0x1.82589994cce13p+0,
    0x1.8ace5422aa0dbp+0, 0x1.93737b0cdc5e5p+0, 0x1.9c49182a3f090p+0, 0x1.a5503b23e255dp+0,
    0x1.ae89f995ad3adp+0, 0x1.b7f76f2fb5e47p+0, 0x1.c199bdd85529cp+0, 0x1.cb720dcef9069p+0,
    0x1.d5818dcfba487p+0, 0x1.dfc97337b9b5fp+0, 0x1.ea4afa2a490dap+0, 0x1.f50765b6e4540p+0,
};
// Centres c of 32 equal slices, in the bits, of [sqrt(1/2), sqrt(2)) and ln c correctly
// rounded (60-digit decimal arithmetic); the slice holding 1 is centred on 1 (ln c = 0), so that
// ln x keeps its relative accuracy near x = 1.
inline constexpr double kLogTable[32][2] = {
    {0x1.6e09e667f3bcdp-1, -0x1.57a3c2d056a46p-2},
    {0x1.7609e667f3bcdp-1, -0x1.41802779d95c5p-2},
    {0x1.7e09e667f3bcdp-1, -0x1.2bd47e58e01c1p-2},
    {0x1.8609e667f3bcdp-1, -0x1.169bce9e7d4aap-2},
    {0x1.8e09e667f3bcdp-1, -0x1.01d16d04af92bp-2},
    {0x1.9609e667f3bcdp-1, -0x1.dae1eb447f6c0p-3},
    {0x1.9e09e667f3bcdp-1, -0x1.b2ec8cb196b8bp-3},
    {0x1.a609e667f3bcdp-1, -0x1.8bbaf3968fdd5p-3},
    {0x1.ae09e667f3bcdp-1, -0x1.6545c59b3912ap-3},
    {0x1.b609e667f3bcdp-1, -0x1.3f86107fdc45fp-3},
    {0x1.be09e667f3bcdp-1, -0x1.1a754293d705bp-3},
    {0x1.c609e667f3bcdp-1, -0x1.ec1a47af6d48ep-4},
    {0x1.ce09e667f3bcdp-1, -0x1.a48f9f71bcb8dp-4},
    {0x1.d609e667f3bcdp-1, -0x1.5e3f5eadccb95p-4},
    {0x1.de09e667f3bcdp-1, -0x1.191ee88982335p-4},
    {0x1.e609e667f3bcdp-1, -0x1.aa484ee54c768p-5},
    {0x1.ee09e667f3bcdp-1, -0x1.248b089249275p-5},
    {0x1.f609e667f3bcdp-1, -0x1.41e778fbde777p-6},
    {0x1.0000000000000p+0, 0x0.0p+0},
    {0x1.0609e667f3bcdp+0, 0x1.7dfcbc3b9f2acp-6},
    {0x1.0e09e667f3bcdp+0, 0x1.b55a3151d4c56p-5},
    {0x1.1609e667f3bcdp+0, 0x1.52424ece8df1ep-4},
    {0x1.1e09e667f3bcdp+0, 0x1.c6730f745b7d0p-4},
    {0x1.2609e667f3bcdp+0, 0x1.1bb7a2cd1bd3dp-3},
    {0x1.2e09e667f3bcdp+0, 0x1.52b180179f0f8p-3},
    {0x1.3609e667f3bcdp+0, 0x1.883b6cb50eb8fp-3},
    {0x1.3e09e667f3bcdp+0, 0x1.bc68287b3a74cp-3},
    {0x1.4609e667f3bcdp+0, 0x1.ef490d76ec989p-3},
    {0x1.4e09e667f3bcdp+0, 0x1.1077194f746f5p-2},
    {0x1.5609e667f3bcdp+0, 0x1.28b34535bdd7bp-2},
    {0x1.5e09e667f3bcdp+0, 0x1.405ffef23fc21p-2},
    {0x1.6609e667f3bcdp+0, 0x1.5783c25053f9cp-2},
};
inline std::uint64_t bits_of(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
inline double double_of(std::uint64_t b)
{
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}
}  // namespace fast_exp_log_detail

inline double log_fast(double x)
{
  namespace d = fast_exp_log_detail;
  if (!(x >= 2.3e-308 && x <= 1.7e308)) return std::log(x);  // zero, negative, subnormal, inf, NaN
  // x = 2^k m, m in [sqrt(1/2), sqrt(2)) (musl's offset trick on the bits), in slice i.
  constexpr std::uint64_t kBase = 0x3fe6a09e667f3bcdull;  // sqrt(1/2)
  const std::uint64_t off = d::bits_of(x) - kBase;
  const std::int64_t k = static_cast<std::int64_t>(off) >> 52;
  const double m = d::double_of(d::bits_of(x) - (static_cast<std::uint64_t>(k) << 52));
  const double *const slice = d::kLogTable[(off >> 47) & 31];
  // ln m = ln c + 2 atanh(s), s = (m - c)/(m + c), |s| < 0.0077 (m - c exact): the series to
  // s^7 leaves s^8/9 < 2e-18 relative.
  const double s = (m - slice[0]) / (m + slice[0]), z = s * s;
  const double series = 2.0 * s + 2.0 * s * z * (1.0 / 3 + z * (1.0 / 5 + z * (1.0 / 7)));
  const double kd = static_cast<double>(k);
  return kd * d::kLn2Hi + (slice[1] + (series + kd * d::kLn2Lo));
}

inline double exp_fast(double x)
{
  namespace d = fast_exp_log_detail;
  if (!(x > -708.0 && x < 709.0)) return std::exp(x);  // overflow, subnormal results, NaN
  // x = (32 q + j) ln2/32 + r, |r| <= ln2/64 (the integer rounded to nearest by the
  // 1.5 * 2^52 shift); e^x = 2^q 2^(j/32) e^r.
  constexpr double kShift = 6755399441055744.0, k32InvLn2 = 46.166241308446828;
  const double kd = (x * k32InvLn2 + kShift) - kShift;
  const double r = (x - kd * (d::kLn2Hi / 32)) - kd * (d::kLn2Lo / 32);
  // e^r - 1 to r^6: r^7/7! < 4e-18.
  const double p =
      r + r * r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720)))));
  const auto k = static_cast<std::int64_t>(kd);
  const double t = d::kExp2[k & 31];
  // Times 2^q through the exponent bits: the result is normal in this range.
  const std::int64_t q = (k - (k & 31)) / 32;
  return d::double_of(d::bits_of(t + t * p) + (static_cast<std::uint64_t>(q) << 52));
}

}  // namespace ohmdem

#endif
