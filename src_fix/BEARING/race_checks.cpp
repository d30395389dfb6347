// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: what stops a run before it goes wrong; see race_checks.h.
#include "BEARING/race_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "atom.h"

namespace ohmdem {

// A load the balls cannot carry elastically would drive the ring through them from the first
// steps: the most loaded ball (F/Nb isotropic; 5 F/Nb under a radial load, above Stribeck's
// 4.37) must stay within the runaway limit of the approach.
std::string load_beyond_elastic_range(RaceLoad load, double load_force, long long balls,
                                      const HertzContact &hertz, double ball_radius)
{
  if (load != RaceLoad::Force && load != RaceLoad::Settle && load != RaceLoad::Radial) return "";
  if (balls <= 0) return "";
  const double per_ball = (load == RaceLoad::Radial ? 5.0 : 1.0) * load_force / balls;
  const double delta = hertz.approach(per_ball);
  if (delta > kRunawayApproachFraction * ball_radius) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "keyword 'force': F = %g N on %lld balls drives the ring through them: the "
                  "most loaded ball (%g N) would need an approach of %g m, %g of the ball radius "
                  "(limit %g, far beyond the elastic range)",
                  load_force, balls, per_ball, delta, delta / ball_radius,
                  kRunawayApproachFraction);
    return msg;
  }
  return "";
}

std::string balls_do_not_fit(double r_in, double r_out, double ball_radius)
{
  const double clearance = r_out - r_in - 2.0 * ball_radius;
  if (clearance < -1e-9 * r_out)
    return "balls of diameter " + std::to_string(2 * ball_radius) +
           " m do not fit between the inner race (radius " + std::to_string(r_in) +
           " m) and the outer race (radius " + std::to_string(r_out) + " m): diametral clearance " +
           std::to_string(clearance) + " m < 0";
  return "";
}

// After read_restart the balls are where the restart left them: a race whose radius or ball
// size changed since (other Dinn, Dext, Db in the deck) would not touch them, or would be inside
// them. Their gap to this race must be the micrometres of a contact.
double worst_ball_gap(const LAMMPS_NS::Atom &atom, int groupbit, bool inner, double cx, double cy,
                      double race_radius, MPI_Comm world)
{
  const double r = race_radius;
  double worst = 0.0;  // largest |gap| of a ball to the race surface (m)
  for (int i = 0; i < atom.nlocal; ++i) {
    if (!(atom.mask[i] & groupbit)) continue;
    const double d = std::hypot(atom.x[i][0] - cx, atom.x[i][1] - cy);
    const double gap = inner ? d - r - atom.radius[i] : r - d - atom.radius[i];
    worst = std::max(worst, std::fabs(gap));
  }
  double all = 0.0;
  MPI_Allreduce(&worst, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

std::string restart_geometry_changed(double all, double radius, double ball_radius)
{
  if (all > 0.01 * ball_radius) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "the balls read from the restart file are up to %g m off this race (radius %g m, "
                  "ball radius %g m): the bearing geometry (race diameter, groove, ball "
                  "diameter) changed since the restart was written; continue with the same "
                  "geometry",
                  all, radius, ball_radius);
    return msg;
  }
  return "";
}

std::string runaway(const HertzContact &hertz, RunawayWatch &watch, RaceStepState &state)
{
  state.reference_fn = watch.mean_fn;
  std::string why = race_runaway(hertz, state);
  if (!why.empty()) return why;
  if (state.balls > 0) {
    ++watch.sound_steps;
    watch.mean_fn +=
        (state.sum_fn / state.balls - watch.mean_fn) / static_cast<double>(watch.sound_steps);
  }
  return why;
}

}  // namespace ohmdem
