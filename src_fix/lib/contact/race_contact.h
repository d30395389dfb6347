// SPDX-License-Identifier: GPL-2.0-or-later
// Ball–race contact of a bearing: a ball in the toroidal groove of an analytic ring, in the
// bearing plane (2D: positions and velocities in x, y; spins about z).
//
// Plain C++ (no LIGGGHTS types): FixBearingRace is a thin adapter around it.
//
// Normal force: exact Hertz for the elliptic contact of the ball in the groove,
// Q = K*delta^(3/2) (K from HertzContact, real curvatures), plus viscous damping set by a
// coefficient of restitution as in LIGGGHTS' hertz model with S_n = dQ/d(delta); no adhesion
// (the total normal force is clamped at zero). Tangential: Coulomb friction with a linear
// tangential spring history (Mindlin stiffness k_t = 8 G* c, c = sqrt(ab) of the contact
// ellipse), viscous tangential damping, |F_t| <= mu*F_n.
#ifndef OHMDEM_RACE_CONTACT_H
#define OHMDEM_RACE_CONTACT_H

#include <algorithm>
#include <cmath>

#include "contact/damping.h"
#include "contact/hertz_contact.h"
#include "contact/vec2.h"

namespace ohmdem {

enum class RaceSide { Inner, Outer };

struct RaceContactModel {
  RaceContactModel(RaceSide side, double ball_radius, double race_radius, double groove_radius,
                   double E_eff, double G_eff, double restitution, double friction);
  RaceSide side;
  double ball_radius;
  HertzContact hertz;  // built for the nominal race radius (the approach is micrometres)
  double G_eff;
  double beta;
  double friction;
  // Mindlin k_t = 8 G* c with c = sqrt(ab) ∝ Q^(1/3) and Q = K delta^(3/2), so
  // k_t = kt_coef * sqrt(delta): no cube root per contact and step.
  double kt_coef;
};

// Kinematic state of one ball and the race at the current step.
struct RaceContactState {
  Vec2 ball_x, ball_v;
  double ball_omega = 0;  // spin about z (rad/s)
  double ball_mass = 0;
  Vec2 race_centre, race_v;  // centre position and velocity
  double race_radius = 0;    // current radius of the race surface (groove bottom)
  double race_radius_rate = 0;
  double race_omega = 0;  // race angular speed about z (rad/s)
  double recess = 0;      // how far the surface falls away under the contact (a pit), m
};

struct RaceContactResult {
  bool touching = false;
  double delta = 0;           // approach (m)
  double fn = 0;              // normal force magnitude (N), >= 0
  double ft = 0;              // tangential force on the ball along t = z x n (N)
  Vec2 normal;                // unit vector from the race centre to the ball centre
  Vec2 point;                 // contact point (middle of the overlap)
  Vec2 force_on_ball;         // total force on the ball (N); the race gets the opposite
  double torque_on_ball = 0;  // about z, about the ball centre (N m)
  double torque_on_race = 0;  // about z, about the race centre, from this ball (N m)
};

// Computes the contact force. `shear` is the tangential spring elongation (m) carried
// from step to step; it is advanced by v_t*dt when update_history is true, and reset to 0
// when the ball is not touching.
// Inline: it runs for every ball at every step, and inlined into the caller its state and
// result stay in registers instead of going through memory.
inline RaceContactResult race_contact(const RaceContactModel &m, const RaceContactState &s,
                                      double dt, bool update_history, double &shear)
{
  RaceContactResult r;
  const double dx = s.ball_x.x - s.race_centre.x;
  const double dy = s.ball_x.y - s.race_centre.y;
  // Not std::hypot: no overflow is possible at bearing scales, and hypot costs several
  // times a sqrt on every contact and step.
  const double dist = std::sqrt(dx * dx + dy * dy);
  // A ball exactly on the race axis has no defined normal: it cannot touch a race anyway.
  if (dist <= 0.0) {
    shear = 0.0;
    return r;
  }
  r.normal = {dx / dist, dy / dist};
  const bool inner = m.side == RaceSide::Inner;
  // side: -1 when the contact is on the centre side of the ball (inner race).
  const double side = inner ? -1.0 : 1.0;
  const double delta =
      (inner ? s.race_radius + m.ball_radius - dist : dist + m.ball_radius - s.race_radius) -
      s.recess;
  r.delta = delta;
  if (delta <= 0.0) {
    shear = 0.0;
    return r;
  }
  r.touching = true;

  // Lever arm from the ball centre to the contact point (middle of the overlap).
  const double arm = m.ball_radius - 0.5 * delta;
  const Vec2 lever{side * arm * r.normal.x, side * arm * r.normal.y};
  r.point = {s.ball_x.x + lever.x, s.ball_x.y + lever.y};

  // Velocities of the two material points at the contact (omega x r with omega along z).
  const Vec2 vb{s.ball_v.x - s.ball_omega * lever.y, s.ball_v.y + s.ball_omega * lever.x};
  const double px = r.point.x - s.race_centre.x;
  const double py = r.point.y - s.race_centre.y;
  // The race surface also moves radially when the ring radius changes (force control).
  const double radial = inner ? s.race_radius_rate : -s.race_radius_rate;
  const Vec2 vr{s.race_v.x - s.race_omega * py + radial * r.normal.x,
                s.race_v.y + s.race_omega * px + radial * r.normal.y};
  const Vec2 vrel{vb.x - vr.x, vb.y - vr.y};
  const Vec2 t{-r.normal.y, r.normal.x};
  const double vn = vrel.x * r.normal.x + vrel.y * r.normal.y;
  const double vt = vrel.x * t.x + vrel.y * t.y;
  const double delta_rate = side * vn;

  // Normal: exact elliptic Hertz + restitution damping (LIGGGHTS' form with S_n = dQ/ddelta).
  const double q = m.hertz.force(delta);
  const double sn = m.hertz.normal_stiffness(delta);
  const double gamma_n = damping_coefficient(m.beta, sn, s.ball_mass);
  r.fn = std::max(0.0, q + gamma_n * delta_rate);

  // Tangential: Mindlin spring on the equivalent contact radius, capped by Coulomb.
  const double kt = m.kt_coef * std::sqrt(delta);  // = 8 G* c(q), see RaceContactModel
  const double gamma_t = damping_coefficient(m.beta, kt, s.ball_mass);
  if (update_history) shear += vt * dt;
  double ft = -kt * shear - gamma_t * vt;
  const double cap = m.friction * r.fn;
  if (std::fabs(ft) > cap) {
    // Sliding: the force sits on the Coulomb cone and the spring holds what it can carry.
    ft = std::copysign(cap, ft);
    shear = kt > 0.0 ? -ft / kt : 0.0;
  }
  r.ft = ft;

  const double fnx = -side * r.fn * r.normal.x;
  const double fny = -side * r.fn * r.normal.y;
  r.force_on_ball = {fnx + ft * t.x, fny + ft * t.y};
  r.torque_on_ball = lever.x * (ft * t.y) - lever.y * (ft * t.x);
  r.torque_on_race = -(px * r.force_on_ball.y - py * r.force_on_ball.x);
  return r;
}

}  // namespace ohmdem

#endif
