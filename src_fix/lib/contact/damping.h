// SPDX-License-Identifier: GPL-2.0-or-later
// Viscous contact damping set by a coefficient of restitution, LIGGGHTS' Hertz form, shared
// by the race and cage contact kernels: gamma = -2 sqrt(5/6) beta sqrt(S m), with S the
// contact stiffness dQ/ddelta (or the tangential one), m the ball mass and
// beta = ln(e)/sqrt(ln(e)^2 + pi^2) (<= 0).
#ifndef OHMDEM_DAMPING_H
#define OHMDEM_DAMPING_H

#include <cmath>

namespace ohmdem {

// Throws std::invalid_argument unless 0 < restitution <= 1.
double restitution_beta(double restitution);

inline double damping_coefficient(double beta, double stiffness, double mass)
{
  return -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(stiffness * mass);
}

}  // namespace ohmdem

#endif
