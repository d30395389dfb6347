// SPDX-License-Identifier: GPL-2.0-or-later
// Cube root for the per-step hot loops (plain C++, no LIGGGHTS types).
//
// Contact areas go as fn^(2/3), so the closed-form bearing resistance takes one cube root per
// ball and step. glibc's cbrt is an out-of-line call of ~130 instructions with a division;
// this inline one is ~30 and lets the balls' roots overlap in the pipeline. Accuracy: within
// 3 ulp of std::cbrt (tests/lib/common/test_fast_cbrt.cpp checks 1e6 arguments over 600 decades);
// zero, negative, subnormal, huge, infinite and NaN arguments go to std::cbrt.
#ifndef OHMDEM_FAST_CBRT_H
#define OHMDEM_FAST_CBRT_H

#include <cmath>
#include <cstdint>
#include <cstring>

namespace ohmdem {

inline double cbrt_fast(double x)
{
  // Normal, positive and small enough that y^3 + 2x below cannot overflow.
  if (!(x >= 2.3e-308 && x <= 1e300)) return std::cbrt(x);
  // First guess from the bits: a third of the biased exponent (Kahan's trick), ~5 bits right.
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = bits / 3 + 0x2A9F7893782DA1CEull;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  // Two Halley steps (cubic convergence: 5 -> 15 -> 45 bits), written as a ratio so that
  // y * (y^3 + 2x) cannot overflow ...
  double y3 = y * y * y;
  y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  y3 = y * y * y;
  y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  // ... and a last Newton step whose correction is small, so its rounding is too.
  return y + (x / (y * y) - y) * (1.0 / 3.0);
}

}  // namespace ohmdem

#endif
