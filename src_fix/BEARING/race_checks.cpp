// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: what stops a run before it goes wrong — a load beyond the contacts'
// elastic range, a restart whose geometry changed, and the per-step runaway check
// (contact/runaway.h; doc/run_status.md).
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "BEARING/fix_bearing_race.h"
#include "atom.h"
#include "contact/race_contact.h"
#include "contact/runaway.h"
#include "error.h"
#include "group.h"
#include "update.h"

using namespace LAMMPS_NS;

// A load the balls cannot carry elastically would drive the ring through them from the first
// steps: the most loaded ball (F/Nb isotropic; 5 F/Nb under a radial load, above Stribeck's
// 4.37) must stay within the runaway limit of the approach.
void FixBearingRace::check_load_in_elastic_range()
{
  if (load_ != Load::Force && load_ != Load::Settle && load_ != Load::Radial) return;
  const bigint balls = group->count(igroup);
  if (balls <= 0) return;
  const double per_ball = (load_ == Load::Radial ? 5.0 : 1.0) * load_force_ / balls;
  const double delta = model_->hertz.approach(per_ball);
  if (delta > ohmdem::kRunawayApproachFraction * ball_radius_) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "keyword 'force': F = %g N on %lld balls drives the ring through them: the "
                  "most loaded ball (%g N) would need an approach of %g m, %g of the ball radius "
                  "(limit %g, far beyond the elastic range)",
                  load_force_, static_cast<long long>(balls), per_ball, delta, delta / ball_radius_,
                  ohmdem::kRunawayApproachFraction);
    error->fix_error(FLERR, this, msg);
  }
}

// After read_restart the balls are where the restart left them: a race whose radius or ball
// size changed since (other Dinn, Dext, Db in the deck) would not touch them, or would be inside
// them. Their gap to this race must be the micrometres of a contact.
void FixBearingRace::check_restart_geometry()
{
  const double r = current_radius();
  double worst = 0.0;  // largest |gap| of a ball to the race surface (m)
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double d = std::hypot(atom->x[i][0] - cx_, atom->x[i][1] - cy_);
    const double gap = inner_ ? d - r - atom->radius[i] : r - d - atom->radius[i];
    worst = std::max(worst, std::fabs(gap));
  }
  double all = 0.0;
  MPI_Allreduce(&worst, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  if (all > 0.01 * ball_radius_) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "the balls read from the restart file are up to %g m off this race (radius %g m, "
                  "ball radius %g m): the bearing geometry (race diameter, groove, ball "
                  "diameter) changed since the restart was written; continue with the same "
                  "geometry",
                  all, radius_, ball_radius_);
    error->fix_error(FLERR, this, msg);
  }
}

// Stops the run when the contacts ran away: the sums are global, so every process reaches the
// same verdict.
void FixBearingRace::check_runaway()
{
  ohmdem::RaceStepState s;
  s.time = time_;
  s.dt = update->dt;
  s.max_fn = max_fn_;
  s.sum_fn = sum_fn_;
  s.fx = fx_;
  s.fy = fy_;
  s.torque = torque_;
  s.u = u_;
  s.cx = cx_;
  s.cy = cy_;
  s.ball_radius = ball_radius_;
  s.ball_mass = ball_mass_;
  s.ring_mass = load_ == Load::None || load_ == Load::Fixed ? 0.0 : ring_mass_;
  s.ring_damping = ring_damp_;
  s.balls = ncontacts_;
  s.reference_fn = mean_fn_;
  const std::string why = ohmdem::race_runaway(model_->hertz, s);
  if (!why.empty()) error->fix_error(FLERR, this, why.c_str());
  if (ncontacts_ > 0) {
    ++sound_steps_;
    mean_fn_ += (sum_fn_ / ncontacts_ - mean_fn_) / static_cast<double>(sound_steps_);
  }
}
