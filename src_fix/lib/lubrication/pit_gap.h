// SPDX-License-Identifier: GPL-2.0-or-later
// A race pit under or near a lubricated contact, modelled as what it is: a strip across the
// raceway, [x1, x2] in the contact's rolling coordinate x, where the race falls away by the
// recess profile r(x). The two integrals it changes: the oil-filled gap around the Hertz
// ellipse out to the wetted circle, and the Hertz zone's film. Plain C++; equations in
// doc/methods/lubricated_contact.md, "Defects: a pit under the film".
#ifndef OHMDEM_LUBRICATION_PIT_GAP_H
#define OHMDEM_LUBRICATION_PIT_GAP_H

#include "lubrication/contact_admittance.h"

namespace ohmdem::lubrication {

// The strip and its profile: r(x) = min(depth, R - sqrt(R^2 - d^2)) for x1 < x < x2, d the
// distance to the nearer edge (pit_recess of contact/defect_geometry.h as a profile: the floor
// where a ball of radius R reaches it, its sag near the edges), 0 outside. edge_radius = 0:
// a flat floor, r = depth across the strip.
struct PitStrip {
  double x1 = 0, x2 = 0;   // edges (m), x1 < x2
  double depth = 0;        // floor depth (m), >= 0
  double edge_radius = 0;  // radius of the ball that rounds the profile (m); 0: flat floor
};
// r(x) (m).
double strip_recess(const PitStrip &p, double x);
// Throws std::invalid_argument for a strip that is no strip (x1 >= x2, a negative or
// non-finite depth or radius).
void check_strip(const PitStrip &p);

// The capacitance of the oil-filled gap h(x, y) = h0 + x^2/(2 rx) + y^2/(2 ry) + r(x) between
// the ellipse (excluded) and the wetted circle: gap_capacitance(g) plus the strip's change,
// eps0 eps_r int_strip [F(A + r) - F(A)] dx, where for fixed x the y-integral is an
// arctangent, F(A) = 2 sqrt(2 ry / A) [atan(Yc / s) - atan(Ye / s)], s = sqrt(2 ry A),
// A = h0 + x^2/(2 rx), Yc = sqrt(r_wet^2 - x^2) (the circle), Ye = a sqrt(1 - x^2/b^2) (the
// ellipse, 0 beyond |x| = b). x by Gauss-Legendre, adaptive, on the pieces split at the
// strip's edges, at the profile's kinks, at +-b and +-r_wet, with x = c sin t (c = b inside
// the ellipse's span, r_wet outside) taking out the square-root ends. A strip that misses
// the circle gives gap_capacitance(g) exactly.
double strip_gap_capacitance(const GapGeometry &g, double eps_r, const PitStrip &p);

// The Hertz ellipse x^2/b^2 + y^2/a^2 <= 1 over a strip: the film is h_c + r(x) and the
// metallic fraction erfc((h_min + r(x)) / (sigma sqrt 2)) at each x (both are functions of x
// only, so the y-integral is the chord 2 a sqrt(1 - x^2/b^2)).
struct HertzFilm {
  double h_c = 0, h_min = 0;  // the film (m) outside the strip; h_c = 0: no entrainment
  double sigma = 0;           // composite RMS roughness (m), > 0
  double a = 0, b = 0;        // semi-axes (m): a across, b along x
};
struct HertzOverPit {
  double metallic = 0;    // area mean of the metallic fraction over the ellipse
  double free_h = 0;      // int (1 - f) / h dA over the ellipse (m): C = eps0 eps C, G = it / rho
  double min_recess = 0;  // smallest r(x) over the ellipse (0 when it reaches past the strip)
};
HertzOverPit hertz_over_pit(const HertzFilm &film, const PitStrip &p);

}  // namespace ohmdem::lubrication

#endif
