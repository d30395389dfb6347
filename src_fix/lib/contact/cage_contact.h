// SPDX-License-Identifier: GPL-2.0-or-later
// Ball–pocket contact of a bearing cage: a rigid ring with N pockets turning about the
// bearing axis. A pocket is a slot bounded by two flat walls parallel to the radial line
// through its centre, at +-(ball radius + clearance) from that line; the cage does not hold
// the balls radially (the races do). Contact: Hertz sphere on flat with the ball and cage
// materials, restitution damping (damping.h) as on the races, frictionless (documented in
// doc/fix_bearing_cage.md). The cage is an electrical insulator: these contacts never enter
// the resistance network.
#ifndef OHMDEM_CAGE_CONTACT_H
#define OHMDEM_CAGE_CONTACT_H

#include <algorithm>
#include <cmath>

#include "contact/damping.h"
#include "contact/hertz_contact.h"
#include "contact/vec2.h"

namespace ohmdem {

struct CageContactModel {
  CageContactModel(double ball_radius, double clearance, double E_eff, double restitution);
  double ball_radius;
  double clearance;  // tangential play of a ball in its pocket, each side (m)
  HertzContact hertz;
  double beta;
};

struct CageContactState {
  Vec2 ball_x, ball_v;
  double ball_mass = 0;
  Vec2 centre;                // cage (bearing) axis
  Vec2 pocket_dir{1.0, 0.0};  // unit vector along the pocket centre line, outwards
  double cage_omega = 0;      // cage angular speed (rad/s)
};

struct CageContactResult {
  bool touching = false;
  double delta = 0;
  double fn = 0;      // normal force magnitude (N)
  double offset = 0;  // signed tangential offset of the ball from the pocket centre (m)
  Vec2 force_on_ball;
  double torque_on_cage = 0;  // about z, about the cage axis (N m)
};

// Inline: it runs for every ball at every step.
inline CageContactResult cage_contact(const CageContactModel &m, const CageContactState &s)
{
  CageContactResult r;
  const Vec2 t{-s.pocket_dir.y, s.pocket_dir.x};  // pocket tangent
  const double dx = s.ball_x.x - s.centre.x;
  const double dy = s.ball_x.y - s.centre.y;
  r.offset = dx * t.x + dy * t.y;
  const double delta = std::fabs(r.offset) - m.clearance;
  r.delta = delta;
  if (delta <= 0.0) return r;
  r.touching = true;
  const double side = r.offset > 0.0 ? 1.0 : -1.0;  // which wall: +t or -t side

  // Contact point on the ball, facing the wall, and the wall's velocity there.
  const double arm = m.ball_radius - 0.5 * delta;
  const Vec2 p{s.ball_x.x + side * arm * t.x, s.ball_x.y + side * arm * t.y};
  const double px = p.x - s.centre.x, py = p.y - s.centre.y;
  const Vec2 vw{-s.cage_omega * py, s.cage_omega * px};
  // Ball spin does not move the contact point along the wall normal: only v matters.
  const double delta_rate = side * ((s.ball_v.x - vw.x) * t.x + (s.ball_v.y - vw.y) * t.y);

  const double q = m.hertz.force(delta);
  const double sn = m.hertz.normal_stiffness(delta);
  const double gamma_n = damping_coefficient(m.beta, sn, s.ball_mass);
  r.fn = std::max(0.0, q + gamma_n * delta_rate);
  r.force_on_ball = {-side * r.fn * t.x, -side * r.fn * t.y};
  r.torque_on_cage = -(px * r.force_on_ball.y - py * r.force_on_ball.x);
  return r;
}

}  // namespace ohmdem

#endif
