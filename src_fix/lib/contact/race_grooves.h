// SPDX-License-Identifier: GPL-2.0-or-later
// Where the 3D bearing's grooves lie (plain C++, no LIGGGHTS types): each race's curvature-
// centre circle from its planar description (radius at the groove bottom R, groove radius Rc,
// the ball radius r) and the bearing's radial internal clearance or nominal contact angle.
// doc/methods/bearing_3d.md, "Grooves".
//
// Clearance c (the total radial play of one ring against the other, as catalogs state it:
// the diametral clearance Pd of Harris): each groove moves away from the balls by c/4 (inner
// rho_c = R + Rc - c/4, outer rho_c = R - Rc + c/4, both at z = 0). A ball that touches both
// then has the free contact angle of Harris, cos(alpha0) = 1 - c/(2A), A = Rci + Rco - 2r.
// Nominal contact angle alpha0 (an angular-contact bearing): the curvature centres lie on the
// line at alpha0 through the ball centre at the pitch radius R + r (inner; R - r outer), at
// Rc - r from it: inner (R + r + (Rc - r) cos a0, (Rc - r) sin a0), outer
// (R - r - (Rc - r) cos a0, -(Rc - r) sin a0).
#ifndef OHMDEM_RACE_GROOVES_H
#define OHMDEM_RACE_GROOVES_H

#include "contact/race_contact.h"

namespace ohmdem {

struct GrooveCircle {
  double centre_radius = 0;  // rho_c (m)
  double centre_z = 0;       // z_c (m)
};

// Throws std::invalid_argument naming the problem: a negative clearance, an angle outside
// [0, 90) degrees, both a clearance and an angle, a groove not larger than the ball.
GrooveCircle groove_circle(RaceSide side, double race_radius, double groove_radius,
                           double ball_radius, double clearance, double alpha0);

// Harris' free contact angle (rad) of a clearance c with A = Rci + Rco - 2r; throws when the
// clearance lets the ball pass between the grooves (c >= 2A: no contact angle exists).
double free_contact_angle(double clearance, double A);

}  // namespace ohmdem

#endif
