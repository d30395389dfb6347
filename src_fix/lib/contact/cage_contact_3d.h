// SPDX-License-Identifier: GPL-2.0-or-later
// Ball-pocket contact of the 3D bearing's cage (plain C++, no LIGGGHTS types): a rigid ring with
// N cylindrical pockets, each a cylinder of radius (ball radius + clearance) about the radial
// line through the pocket's centre at the cage's axial position, turning about the bearing axis
// and free to slide along it. A ball touches its pocket when its centre lies farther than the
// clearance from that line (tangentially, axially or both): the play is the planar cage's, in
// every direction across the pocket. Normal force as the planar pocket (cage_contact.h: Hertz
// sphere on flat with restitution damping, frictionless); the cage does not hold the balls
// radially. In the bearing plane (no axial offset) it is the planar pocket exactly.
#ifndef OHMDEM_CAGE_CONTACT_3D_H
#define OHMDEM_CAGE_CONTACT_3D_H

#include <algorithm>
#include <cmath>

#include "contact/cage_contact.h"
#include "contact/vec3.h"

namespace ohmdem {

struct CageContactState3d {
  Vec3 ball_x, ball_v;
  double ball_mass = 0;
  Vec3 centre;                // a point of the bearing axis at the cage's axial position (m)
  Vec2 pocket_dir{1.0, 0.0};  // unit vector along the pocket's centre line, outwards
  double cage_omega = 0;      // rad/s about z
  double cage_vz = 0;         // axial velocity of the cage (m/s)
};

struct CageContactResult3d {
  bool touching = false;
  double delta = 0, fn = 0;
  double offset = 0;        // tangential offset of the ball from the pocket's axis (m)
  double axial_offset = 0;  // axial offset (m)
  Vec3 force_on_ball;
  double torque_on_cage = 0;  // about z (N m)
  double axial_on_cage = 0;   // force on the cage along z (N)
};

inline CageContactResult3d cage_contact_3d(const CageContactModel &m, const CageContactState3d &s)
{
  CageContactResult3d r;
  const Vec2 t{-s.pocket_dir.y, s.pocket_dir.x};
  const double dx = s.ball_x.x - s.centre.x, dy = s.ball_x.y - s.centre.y;
  r.offset = dx * t.x + dy * t.y;
  r.axial_offset = s.ball_x.z - s.centre.z;
  const double d = std::sqrt(r.offset * r.offset + r.axial_offset * r.axial_offset);
  const double delta = d - m.clearance;
  r.delta = delta;
  if (!(delta > 0.0)) return r;
  r.touching = true;
  const Vec3 nu{r.offset / d * t.x, r.offset / d * t.y, r.axial_offset / d};  // toward the wall
  const double arm = m.ball_radius - 0.5 * delta;
  const Vec3 p = s.ball_x + arm * nu;
  const double px = p.x - s.centre.x, py = p.y - s.centre.y;
  const Vec3 vw{-s.cage_omega * py, s.cage_omega * px, s.cage_vz};
  const double delta_rate = dot(s.ball_v - vw, nu);
  const double q = m.hertz.force(delta);
  const double gamma_n = damping_coefficient(m.beta, m.hertz.normal_stiffness(delta), s.ball_mass);
  r.fn = std::max(0.0, q + gamma_n * delta_rate);
  r.force_on_ball = -r.fn * nu;
  r.torque_on_cage = -(px * r.force_on_ball.y - py * r.force_on_ball.x);
  r.axial_on_cage = -r.force_on_ball.z;
  return r;
}

}  // namespace ohmdem

#endif
