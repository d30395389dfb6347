// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: what stops a run before it goes wrong — a load beyond the contacts'
// elastic range, a restart whose geometry changed, and the per-step runaway check
// (contact/runaway.h; doc/run_status.md). Plain functions of the values they are given: each
// returns "" when all is well, else the message the fix stops the run with.
#ifndef OHMDEM_STYLE_RACE_CHECKS_H
#define OHMDEM_STYLE_RACE_CHECKS_H

#include <mpi.h>

#include <string>

#include "BEARING/race_settings.h"
#include "contact/hertz_contact.h"
#include "contact/runaway.h"

namespace LAMMPS_NS {
class Atom;
}

namespace ohmdem {

// A load the balls cannot carry elastically (`load_force` N on `balls` balls, this step's
// value of a force variable).
std::string load_beyond_elastic_range(RaceLoad load, double load_force, long long balls,
                                      const HertzContact &hertz, double ball_radius);

// Balls of radius `ball_radius` between an inner race of radius r_in and an outer one of r_out.
std::string balls_do_not_fit(double r_in, double r_out, double ball_radius);

// Collective: the largest |gap| (m) of a ball of the group to the race surface of radius
// `race_radius` about (cx, cy), over all processes.
double worst_ball_gap(const LAMMPS_NS::Atom &atom, int groupbit, bool inner, double cx, double cy,
                      double race_radius, MPI_Comm world);
// After read_restart: the balls must be within a contact's micrometres of the race.
std::string restart_geometry_changed(double worst_gap, double radius, double ball_radius);

// The running mean load per touching ball of the steps that passed, for the messages.
struct RunawayWatch {
  double mean_fn = 0;  // N
  long long sound_steps = 0;
};
// The runaway check of a step (the sums are global: every process gives the same verdict),
// with state.reference_fn set from `watch`; a sound step with contacts updates `watch`.
std::string runaway(const HertzContact &hertz, RunawayWatch &watch, RaceStepState &state);

}  // namespace ohmdem

#endif
