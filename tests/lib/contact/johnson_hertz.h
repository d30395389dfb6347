// SPDX-License-Identifier: GPL-2.0-or-later
// The elliptic Hertz contact in Johnson's pressure form (Contact Mechanics, section 4.3), with
// libstdc++'s elliptic integrals, for the 3D contact tests: independent of the kernel's
// ellipticity form and AGM (contact/hertz_contact.cpp). For the half curvature sums A' <= B'
// and an ellipse of eccentricity e (m = e^2 = 1 - b^2/a^2):
//   A' = p0 b (K - E) / (E* m a^2),   B' = p0 b (E / (1 - m) - K) / (E* m a^2),
//   delta = p0 b K / E*,   P = (2/3) pi a b p0.
#ifndef OHMDEM_TESTS_JOHNSON_HERTZ_H
#define OHMDEM_TESTS_JOHNSON_HERTZ_H

#include <cmath>

#include "test_constants.h"

namespace ohmdem::test {

struct JohnsonHertz {
  double a, b, delta, E_ecc;  // semi-axes, approach at the load P, E(e) of the ellipse
};

// sum1, sum2: the full curvature sums (1/m) of the two principal planes.
inline JohnsonHertz johnson_hertz(double sum1, double sum2, double Estar, double P)
{
  const double A = 0.5 * std::fmin(sum1, sum2), B = 0.5 * std::fmax(sum1, sum2);
  auto ratio = [](double m) {
    const double K = std::comp_ellint_1(std::sqrt(m)), E = std::comp_ellint_2(std::sqrt(m));
    return (E / (1 - m) - K) / (K - E);
  };
  double lo = 1e-14, hi = 1 - 1e-14;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio(mid) < B / A ? lo : hi) = mid;
  }
  const double m = 0.5 * (lo + hi), k = std::sqrt(m);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  const double a = std::cbrt(3 * P * (K - E) / (2 * kPi * Estar * m * A));
  return {a, a * std::sqrt(1 - m), 3 * P * K / (2 * kPi * a * Estar), E};
}

// K in Q = K delta^1.5.
inline double johnson_stiffness(double sum1, double sum2, double Estar)
{
  const JohnsonHertz h = johnson_hertz(sum1, sum2, Estar, 1.0);
  return 1.0 / (h.delta * std::sqrt(h.delta));
}

}  // namespace ohmdem::test

#endif
