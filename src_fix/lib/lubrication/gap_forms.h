// SPDX-License-Identifier: GPL-2.0-or-later
// The closed form of the gap integral's midpoint rule (contact_admittance.cpp,
// gap_capacitance), shared with race_admittance.cpp. Plain C++; doc/methods/lubricated_contact.md.
#ifndef OHMDEM_LUBRICATION_GAP_FORMS_H
#define OHMDEM_LUBRICATION_GAP_FORMS_H

#include <cmath>

namespace ohmdem::lubrication::gap_forms {

// Midpoints of a quarter turn: the gap integrand is even in x and in y.
constexpr int kQuarter = 32;

// The midpoint rule on M = 4 kQuarter angles applied to ln(A cos^2 + B sin^2), in closed
// form: with sA = sqrt A, sB = sqrt B, A cos^2 + B sin^2 = ((sA + sB)/2)^2 |1 + rho e^(2i phi)|^2,
// rho = (sA - sB)/(sA + sB), and the mean of cos(2 n phi) over the midpoints is (-1)^k for
// 2n = k M, else 0, so the rule gives 2 ln((sA + sB)/2) + (4/M) ln(1 + rho^(M/2)) -- the
// exact integral plus the rule's own aliasing term, i.e. the same number as the sum of the
// M logarithms. Returns sA + sB and 1 + rho^(M/2).
struct FormMean {
  double s = 0, y = 1;
};
inline FormMean form_mean(double sa, double sb)
{
  static_assert(kQuarter == 32, "rho^(M/2) = rho^64 below");
  const double s = sa + sb;
  double r = (sa - sb) / s;
  for (int i = 0; i < 6; ++i) r *= r;
  return {s, 1.0 + r};
}

// ln(y) / kQuarter for the aliasing terms' y = 1 + eps: mostly |eps| < 1e-6, where four
// terms of the series leave an error below eps^5 / 5 (1e-31): no logarithm.
template <class Log>
double aliasing(double y, Log log)
{
  const double e = y - 1.0;
  if (std::fabs(e) < 1e-6) return e * (1.0 - e * (0.5 - e * (1.0 / 3.0 - 0.25 * e))) / kQuarter;
  return log(y) / kQuarter;
}

}  // namespace ohmdem::lubrication::gap_forms

#endif
