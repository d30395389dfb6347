// SPDX-License-Identifier: GPL-2.0-or-later
// The conduction laws, each written once, plain C++ (no LIGGGHTS types): the bulk law (paper
// eq. 1, inside a particle), the constriction law (Holm, across a contact spot) and the mixing
// rule of two bodies' resistivities. conduction/conduction_model.h composes them.
//
// Paper eq. 1: inside a conducting particle k, two of its contact spots i, j (areas S_i, S_j,
// angle theta_ij between them seen from the particle centre) are joined by
//   C_ij = gamma * S_i * S_j / (2 * V_k * (1 - cos theta_ij)).
// It diverges as theta -> 0. Two spots of radii c = sqrt(S/pi) on a sphere of radius r
// cannot be closer than touching, so their centres are at least c_i + c_j apart along the
// surface: theta >= theta_min = (c_i + c_j) / r (capped at pi). This bound is applied, which
// keeps C_ij finite. Derivation, limits and tests: doc/methods/conduction_network.md.
#ifndef OHMDEM_CONDUCTANCE_LAWS_H
#define OHMDEM_CONDUCTANCE_LAWS_H

#include <cstddef>
#include <functional>

#include "common/constants.h"
#include "contact/hertz_contact.h"
#include "network/conduction_network.h"

namespace ohmdem {

double sphere_volume(double radius);
// Radius of the circle of area S (the equivalent radius of an elliptic spot).
double spot_radius(double area);
// Angle (rad, in [0, pi]) between vectors u and v, accurate also near 0 and pi
// (atan2(|u x v|, u.v), not acos). 0 if either vector is zero.
double angle_between(const double u[3], const double v[3]);
// Smallest admissible angle between two spots on a sphere of radius r: (c_i + c_j) / r,
// capped at pi.
double min_spot_angle(double area_i, double area_j, double radius);

struct Eq1Result {
  double conductance;  // S
  double theta;        // rad, angle actually used (>= the geometric one)
  bool clamped;        // theta was raised to min_spot_angle
};

// Paper eq. 1 with the theta clamp. gamma (S/m), areas (m^2), volume (m^3), theta (rad),
// radius (m). 1 - cos(theta) is evaluated as 2 sin^2(theta/2) (no cancellation at small
// angles). Zero (never NaN) if an area is zero, or gamma, volume or radius are not > 0.
Eq1Result eq1_conductance(double gamma, double area_i, double area_j, double volume, double theta,
                          double radius);

// Holm constriction resistance (Ohm) of one elliptic spot with semi-axes a >= b (m) (the
// arguments are swapped if b > a), resistivity rho_e = 1/gamma (Ohm m):
// R_c = rho_e K(e^2) / (pi a), e^2 = 1 - b^2/a^2; rho_e/(2a) for a circle.
// +infinity for a zero-size spot (a <= 0 or b <= 0): the caller treats that as "no contact".
double holm_resistance(double rho_e, double a, double b);

// Holm's factor K(e^2)/pi of an ellipse of axis ratio b/a = 1/ellipticity: the constriction
// is rho * holm_factor / a (what holm_resistance(1, 1, b/a) gives).
double holm_factor(double ellipticity);

// The resistivity of a spot between two bodies of conductivities gamma_1, gamma_2 (S/m): the
// mean of their resistivities, (1/gamma_1 + 1/gamma_2) / 2 (Ohm m).
inline double mixed_resistivity(double gamma_1, double gamma_2)
{
  return 0.5 * (1.0 / gamma_1 + 1.0 / gamma_2);
}

// Two conductances in series (a split contact: Holm constriction + particle path).
double series_conductance(double g1, double g2);

// One conducting contact spot of a particle.
struct ContactSpot {
  NodeKey node;     // network node of this contact (the electrode's key on an electrode)
  double point[3];  // contact point (m)
  double area;      // contact area S (m^2)
};

struct ConductingParticle {
  double centre[3];  // m
  double radius;     // m
  double volume;     // m^3 (sphere_volume(radius) for a sphere)
  double gamma;      // electrical conductivity (S/m); 0 for an insulator
};

// Adds the eq. 1 conductance between every pair of the particle's spots (n(n-1)/2 edges; a
// particle with two spots is one conductance). Pairs whose nodes coincide (both on one
// electrode: no current inside) and zero conductances (zero area, gamma = 0) are skipped.
// Returns the number of pairs whose angle was clamped.
// Eq. 1 from the two contact vectors u, v (particle centre to contact point). For an obtuse
// angle 1 - cos(theta) = 1 - u.v/(|u||v|) >= 1 has no cancellation and the theta clamp cannot
// apply (unless the spots are larger than the sphere), so no trigonometric call is needed;
// otherwise this is eq1_conductance(gamma, .., angle_between(u, v), radius).conductance.
double eq1_conductance_between(double gamma, double area_i, double area_j, double volume,
                               const double u[3], const double v[3], double radius);

// `on_edge`, if given, is told every conductance added (e.g. to draw it in a VTK file).
using EdgeVisitor = std::function<void(const ContactSpot &, const ContactSpot &, double g)>;
int add_particle_conductances(ConductionNetwork &net, const ConductingParticle &p,
                              const ContactSpot *spots, std::size_t n,
                              const EdgeVisitor &on_edge = nullptr);
// The same conductances, each given to `visit` (g > 0) instead of a network.
int for_each_particle_conductance(const ConductingParticle &p, const ContactSpot *spots,
                                  std::size_t n, const EdgeVisitor &visit);

}  // namespace ohmdem

#endif
