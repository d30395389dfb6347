// Ball–pocket contact of a bearing cage: a rigid ring with N pockets turning about the
// bearing axis. A pocket is a slot bounded by two flat walls parallel to the radial line
// through its centre, at +-(ball radius + clearance) from that line; the cage does not hold
// the balls radially (the races do). Contact: Hertz sphere on flat with the ball and cage
// materials, restitution damping as in race_contact.h, frictionless (documented in
// doc/fix_bearing_cage.md). The cage is an electrical insulator: these contacts never enter
// the resistance network.
#ifndef OHMDEM_CAGE_CONTACT_H
#define OHMDEM_CAGE_CONTACT_H

#include "hertz_contact.h"
#include "race_contact.h"

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
  Vec2 centre;               // cage (bearing) axis
  double pocket_angle = 0;   // angular position of the pocket centre line (rad)
  double cage_omega = 0;     // cage angular speed (rad/s)
};

struct CageContactResult {
  bool touching = false;
  double delta = 0;
  double fn = 0;             // normal force magnitude (N)
  double offset = 0;         // signed tangential offset of the ball from the pocket centre (m)
  Vec2 force_on_ball;
  double torque_on_cage = 0;  // about z, about the cage axis (N m)
};

CageContactResult cage_contact(const CageContactModel &model, const CageContactState &s);

}  // namespace ohmdem

#endif
