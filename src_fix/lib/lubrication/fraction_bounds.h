// SPDX-License-Identifier: GPL-2.0-or-later
// When a contact's metallic fraction f = erfc(x) cannot matter, so that it is not computed
// (RaceAdmittance::contact; race_lanes.h does the same operations lane by lane, for the same
// decisions). f is negligible where 1 - f rounds to 1 (f <= 2^-54) and f g_dry is below
// 1e-17 of the leakage, less than half an ulp of it: then C and G keep every bit. With x > 0,
// f < bound(x) = e^(-x^2) / (x sqrt(pi)).
#ifndef OHMDEM_LUBRICATION_FRACTION_BOUNDS_H
#define OHMDEM_LUBRICATION_FRACTION_BOUNDS_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "common/constants.h"
#include "common/fast_exp_log.h"

namespace ohmdem::lubrication::fraction_bounds {

// 2^-k for 0 <= k <= 1022, from the exponent bits.
inline double pow2_neg(int k)
{
  const std::uint64_t bits = static_cast<std::uint64_t>(1023 - k) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// Whether a fraction of at most f cannot matter.
inline bool negligible(double f, double g_dry, double leak)
{
  return f <= 0x1p-54 && f * g_dry <= 1e-17 * leak;
}

// k = floor(x^2 / ln 2), taken a hair low, at most 1000: e^(-x^2) <= 2^-k.
inline double exponent(double x)
{
  return std::min(std::floor(x * x * (1.4426950408889634 * (1.0 - 1e-12))), 1000.0);
}

// From x = 6, 1/(x sqrt(pi)) < 0.1: bound(x) < 0.1 2^-k, without an exponential.
inline double cheap(double k)
{
  return 0.1 * pow2_neg(static_cast<int>(k));
}

inline double bound(double x)
{
  return exp_fast(-x * x) / (x * std::sqrt(kPi));
}

// Whether bound(x) fails negligible(): while k < 1000, x^2 / ln 2 < k + 1 + 1e-9, so
// e^(-x^2) > 2^-(k+2), and sqrt(pi) < 1.7725: bound(x) > 2^-(k+2) / (1.7725 x). Where this
// lower bound fails a test by more than rounding (the factor 1.0001), bound(x) fails it too,
// and its exponential can be skipped (in a run-up, most contacts lie here).
inline bool cannot_pass(double x, double k, double g_dry, double leak)
{
  if (!(k < 1000.0)) return false;
  const double low = pow2_neg(static_cast<int>(k) + 2), scale = (1.7725 * 1.0001) * x;
  return low > 0x1p-54 * scale || low * g_dry > 1e-17 * leak * scale;
}

}  // namespace ohmdem::lubrication::fraction_bounds

#endif
