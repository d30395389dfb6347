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

#include "hertz_contact.h"

namespace ohmdem {

struct Vec2 {
  double x = 0;
  double y = 0;
};

enum class RaceSide { Inner, Outer };

// Damping ratio factor of LIGGGHTS' Hertz model: beta = ln(e)/sqrt(ln(e)^2 + pi^2) (<= 0).
double restitution_beta(double restitution);

struct RaceContactModel {
  RaceContactModel(RaceSide side, double ball_radius, double race_radius, double groove_radius,
                   double E_eff, double G_eff, double restitution, double friction);
  RaceSide side;
  double ball_radius;
  HertzContact hertz;  // built for the nominal race radius (the approach is micrometres)
  double G_eff;
  double beta;
  double friction;
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
};

struct RaceContactResult {
  bool touching = false;
  double delta = 0;    // approach (m)
  double fn = 0;       // normal force magnitude (N), >= 0
  double ft = 0;       // tangential force on the ball along t = z x n (N)
  Vec2 normal;         // unit vector from the race centre to the ball centre
  Vec2 point;          // contact point (middle of the overlap)
  Vec2 force_on_ball;  // total force on the ball (N); the race gets the opposite
  double torque_on_ball = 0;  // about z, about the ball centre (N m)
  double torque_on_race = 0;  // about z, about the race centre, from this ball (N m)
};

// Computes the contact force. `shear` is the tangential spring elongation (m) carried
// from step to step; it is advanced by v_t*dt when update_history is true, and reset to 0
// when the ball is not touching.
RaceContactResult race_contact(const RaceContactModel &model, const RaceContactState &s,
                               double dt, bool update_history, double &shear);

}  // namespace ohmdem

#endif
