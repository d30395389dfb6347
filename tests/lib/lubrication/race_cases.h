// SPDX-License-Identifier: GPL-2.0-or-later
// Races and contacts for the tests of RaceAdmittance (test_race_admittance*.cpp): races like
// the 6208's inner and outer ones in VG68 and thinner and thicker oils, and the ContactInput of
// contact_admittance() (the reference) for a contact of such a race.
#ifndef OHMDEM_TEST_RACE_CASES_H
#define OHMDEM_TEST_RACE_CASES_H

#include <cmath>

#include "common/fast_cbrt.h"
#include "lubrication/contact_admittance.h"
#include "lubrication/race_admittance.h"

namespace ohmdem::lubrication::test {

inline double rel(double a, double b)
{
  return a == b ? 0.0 : std::fabs(a / b - 1.0);
}

// A race like the 6208's inner (Rx 5 mm, conformal groove) or outer one, in the oil VG68.
inline RaceInput race(int n, double r_wet)
{
  RaceInput r;
  r.rx = 4e-3 + 4e-3 * (n % 3);
  r.ry = 0.05 + 0.1 * (n % 2);
  r.e_prime = 2.2e11;
  r.a_coef = 2.0e-4 + 1e-4 * (n % 2);
  r.b_coef = 3.0e-5 + 1e-5 * (n % 3);
  // VG68 at 40 C, then thinner and thicker oils (hot and cold), other permittivities.
  r.eta = 0.06 * std::pow(10.0, (n % 5) * 0.6 - 1.2);
  r.alpha = 1.5e-8 + 0.5e-8 * (n % 4);
  r.eps_r = 2.07 + 0.4 * (n % 3);
  r.sigma = 1e-7;
  r.r_wet = r_wet;
  r.resistivity = 1e12;
  return r;
}

inline ContactInput input(const RaceInput &r, double fn, double speed, double g_dry, double recess)
{
  ContactInput in;
  const double q = ohmdem::cbrt_fast(fn);  // HertzContact::ellipse
  in.a = r.a_coef * q;
  in.b = r.b_coef * q;
  in.film = FilmInput{fn, speed, r.rx, r.ry, r.e_prime, r.eta, r.alpha, in.a / in.b};
  in.sigma = r.sigma;
  in.r_wet = r.r_wet;
  in.eps_r = r.eps_r;
  in.resistivity = r.resistivity;
  in.g_dry = g_dry;
  in.recess = recess;
  return in;
}

}  // namespace ohmdem::lubrication::test

#endif
