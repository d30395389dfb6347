// SPDX-License-Identifier: GPL-2.0-or-later
// Elastohydrodynamic film of an elliptical contact: Hamrock and Dowson's central and minimum
// film thickness (fully flooded, isothermal, Newtonian; Hamrock and Dowson 1977, Hamrock 1994
// ch. 22), and the film parameter. Plain C++; doc/methods/lubricated_contact.md.
#ifndef OHMDEM_LUBRICATION_EHL_FILM_H
#define OHMDEM_LUBRICATION_EHL_FILM_H

namespace ohmdem::lubrication {

// One contact's inputs, SI units.
struct FilmInput {
  double load = 0;     // w, normal load (N)
  double speed = 0;    // u, MEAN entrainment speed (u1 + u2) / 2 (m/s)
  double rx = 0;       // effective radius in the rolling direction (m)
  double ry = 0;       // effective radius across it (m)
  double e_prime = 0;  // E' = 2 / [(1 - nu1^2)/E1 + (1 - nu2^2)/E2] (Pa), twice Hertz's E*
  double eta = 0;      // viscosity at the inlet, atmospheric pressure (Pa s)
  double alpha = 0;    // pressure-viscosity coefficient (1/Pa)
  double k = 1;        // ellipticity a/b, a across the rolling direction
};

struct Film {
  double central = 0;  // h_c (m)
  double minimum = 0;  // h_min (m)
};

// h_c/Rx = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k))
// h_min/Rx = 3.63 U^0.68 G^0.49 W^-0.073 (1 - e^(-0.68 k))
// U = eta u / (E' Rx), G = alpha E', W = w / (E' Rx^2). Zero film for u <= 0 (no entrainment)
// or w <= 0 (no load: the caller models the gap instead).
Film hamrock_dowson(const FilmInput &in);

// The parts of those films that do not depend on the contact's load and speed: the
// prefactors rx 2.69 (eta/(E' rx))^0.67 G^0.53 (1/(E' rx^2))^-0.067 (and the minimum's) and the
// ellipticity factors. hamrock_dowson multiplies them by u^0.67 w^-0.067 (u^0.68 w^-0.073);
// a race's contacts share them (race_admittance.h).
Film film_prefactors(double eta, double e_prime, double rx, double alpha);
Film ellipticity_factors(double k);

// lambda = h_min / sigma, sigma = sqrt(Rq1^2 + Rq2^2) the composite RMS roughness (> 0).
inline double film_parameter(double h_min, double sigma)
{
  return h_min / sigma;
}

}  // namespace ohmdem::lubrication

#endif
