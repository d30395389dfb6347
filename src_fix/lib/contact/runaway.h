// SPDX-License-Identifier: GPL-2.0-or-later
// Signs that the integration of a race and its balls has run away (a time step too large for
// the contact stiffness, a ring or ball without mass, a damping that overshoots): past them the
// physics is gone and every output would be garbage, so the run must stop and say why.
//
// Plain C++ (no LIGGGHTS types); FixBearingRace asks it once per step (a few flops) and stops
// with error->all on a verdict. doc/run_status.md lists the limits.
#ifndef OHMDEM_RUNAWAY_H
#define OHMDEM_RUNAWAY_H

#include <string>

#include "contact/hertz_contact.h"

namespace ohmdem {

// The state of one race after a force evaluation (global sums: the same on every process).
struct RaceStepState {
  double time = 0;                        // simulated time (s)
  double dt = 0;                          // time step (s)
  double max_fn = 0, sum_fn = 0;          // largest and summed ball-race normal forces (N)
  double fx = 0, fy = 0, torque = 0;      // reactions on the ring
  double u = 0, cx = 0, cy = 0;           // ring interference and centre offset (m)
  double ball_radius = 0, ball_mass = 0;  // (m, kg)
  double ring_mass = 0;                   // 0: the ring has no free degree of freedom
  double ring_damping = 0;                // viscous damping of the ring (N s/m)
  int balls = 0;                          // balls in contact (the ring's springs)
  double reference_fn = 0;                // a healthy load per ball (N): for the critical step
  // The cage on a ball (another body's step the race cannot see: fix bearing/cage's), 0 when
  // there is none: sqrt(mu/k) of a pocket contact, mu the reduced mass of cage and ball.
  double cage_step = 0, cage_mass = 0;
};

// An approach beyond this fraction of the ball radius is far outside the elastic range of a
// steel contact (yield starts near 1e-4): the integration has run away.
constexpr double kRunawayApproachFraction = 0.02;
// A ring centre or radius that moved by this fraction of the ball radius has left the balls.
constexpr double kRunawayOffsetFraction = 0.5;

// The critical step of a Hertz contact at the load fn: sqrt(m / k), k = dQ/d(delta).
double hertz_critical_step(const HertzContact &h, double mass, double fn);

// "" while the state is sound; else what ran away, with the numbers and the likely cause: the
// stiffest of the critical steps (a ball on its contact, the ring on its contacts, the ring's
// viscous kick 2M/C, the cage on a ball), named first, with the others after it.
std::string race_runaway(const HertzContact &h, const RaceStepState &s);

}  // namespace ohmdem

#endif
