// SPDX-License-Identifier: GPL-2.0-or-later
// The complementary error function for the lubricated contact's metallic fraction, inline
// (plain C++). glibc's erfc with its exponentials costs ~160 instructions here; this one 66
// plus its exponential's ~40, within 3e-14 relative of it up to x = 6 and 2e-13 up to 26 (the
// rounding of x^2 in the exponent; tests/lib/common/test_fast_erfc.cpp): far inside the
// per-contact accuracy budget of doc/methods/lubricated_contact.md, "Speed".
//
// For x >= 0, with t = 2/(2 + x) and s = 2t - 1 = (2 - x)/(2 + x) in (-1, 1]:
//   erfc(x) = t exp(-x^2 + g(s)),  g(s) = ln(erfc(x)/t) + x^2,
// g smooth on [-1, 1] (g(-1) = -ln(2 sqrt(pi)), the limit x -> inf): the transformation of
// Numerical Recipes' erfccheb. The polynomial is ours (scripts/fast_erfc_coefficients.py): 22
// Chebyshev terms of g from 60 nodes in 50-digit arithmetic (the dropped ones add to 9.3e-15),
// in powers of s, summed in Estrin's form (common/estrin.h; their |coefficients| add to 1.46:
// no cancellation). So erfc to ~1e-14 relative plus the rounding of the exponent, ~x^2 ulp.
#ifndef OHMDEM_FAST_ERFC_H
#define OHMDEM_FAST_ERFC_H

#include <cmath>

#include "common/estrin.h"
#include "common/fast_exp_log.h"

namespace ohmdem {

// g(s) in powers of s, constant term first (erfc_fast; common/lanes.h users share it).
inline constexpr double kErfcG[22] = {
    -0.6717940840566903,     0.6726432239778217,    0.047343306841332665,
    -0.04689561024571166,    -0.009872689339502133, 0.008824938935263605,
    0.0017589330595699703,   -0.002345817040411264, -0.0001462420635759325,
    0.0006737090513593518,   -9.37625060511117e-05, -0.00017442596999566427,
    7.150155985697925e-05,   3.206559421540822e-05, -3.0432773413602292e-05,
    -4.0637851031393504e-07, 8.966703359129732e-06, -2.352944696447295e-06,
    -1.7233176592624477e-06, 8.549461192071435e-07, 1.6415045186187208e-07,
    -1.1818313828393028e-07,
};

inline double erfc_fast(double x)
{
  // erfc(0) = 1 exactly (the dry limit: a metallic fraction of 1 keeps G = g_dry to the bit);
  // negative x, NaN and x > 26 (erfc below 1e-295) go to the library.
  if (x == 0.0) return 1.0;
  if (!(x > 0.0 && x <= 26.0)) return std::erfc(x);
  if (x < 0.5) {
    // 1 - erf(x), erf by its Taylor series 2/sqrt(pi) sum (-x^2)^n / (n! (2n + 1)) to n = 11
    // (the next term < 2e-18 of erf): the metallic fraction near 1 keeps 1 - f to an ulp,
    // as glibc's (Rb equals the dry R as lambda -> 0).
    static constexpr double kE[12] = {1.0,
                                      -1.0 / 3,
                                      1.0 / (2 * 5),
                                      -1.0 / (6 * 7),
                                      1.0 / (24 * 9),
                                      -1.0 / (120 * 11),
                                      1.0 / (720 * 13),
                                      -1.0 / (5040 * 15),
                                      1.0 / (40320 * 17),
                                      -1.0 / (362880 * 19),
                                      1.0 / (3628800.0 * 21),
                                      -1.0 / (39916800.0 * 23)};
    const double z = x * x;
    double sum = kE[11];
#pragma GCC unroll 16
    for (int n = 10; n >= 0; --n) sum = sum * z + kE[n];
    return 1.0 - 1.1283791670955126 * x * sum;  // 2/sqrt(pi)
  }
  const double t = 2.0 / (2.0 + x), s = 2.0 * t - 1.0;
  // Estrin's form: a chain of ~10 dependent operations instead of Horner's 42.
  const double g = estrin::polynomial<22>(kErfcG, s);
  return t * exp_fast(g - x * x);
}

}  // namespace ohmdem

#endif
