// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - the common base of fix bearing/race and fix bearing/cage.
------------------------------------------------------------------------- */

#include "BEARING/fix_bearing_body.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "atom.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "support/peratom_state.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixBearingBody::FixBearingBody(LAMMPS *lmp, int narg, char **arg, int vector_size, int peratom_cols,
                               const char *state_name)
    : Fix(lmp, narg, arg), state_name_(std::string(state_name) + id)
{
  vector_flag = 1;
  size_vector = vector_size;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = peratom_cols;
  peratom_freq = 1;
  restart_global = 1;
  array_atom = nullptr;
}

int FixBearingBody::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE | FINAL_INTEGRATE;
}

void FixBearingBody::create_state(const std::vector<std::string> &defaults)
{
  // In a fix property/atom: it migrates with the atom between processes and is written to
  // restart files.
  ohmdem::create_peratom_state(modify, state_name_, defaults, style);
}

void FixBearingBody::find_state()
{
  state_ = ohmdem::find_peratom_state(modify, state_name_, style);
}

void FixBearingBody::find_defects(bool cage)
{
  defects_.clear();
  for (int k = 0; k < modify->nfix; ++k)
    if (const auto *d = dynamic_cast<const ohmdem::BearingDefect *>(modify->fix[k]))
      if (cage ? d->acts_on_cage() : d->acts_on_races()) defects_.push_back(d);
}

FixBearingBody::GroupBalls FixBearingBody::scan_group() const
{
  double rmin = 1e300, rmax = -1e300;
  int tmin = 1 << 30, tmax = -1;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    rmin = std::min(rmin, atom->radius[i]);
    rmax = std::max(rmax, atom->radius[i]);
    tmin = std::min(tmin, atom->type[i]);
    tmax = std::max(tmax, atom->type[i]);
  }
  double rr[2] = {rmin, -rmax}, rg[2];
  MPI_Allreduce(rr, rg, 2, MPI_DOUBLE, MPI_MIN, world);
  int tt[2] = {tmin, -tmax}, tg[2];
  MPI_Allreduce(tt, tg, 2, MPI_INT, MPI_MIN, world);
  return {tg[0] == (1 << 30), rg[0], -rg[1], tg[0], -tg[1]};
}

bool FixBearingBody::reapply_restored_forces(int fx, int fy, int tz)
{
  if (!restored_) return false;
  restored_ = false;
  array_atom = state_->array_atom;
  double **f = atom->f, **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    f[i][0] += array_atom[i][fx];
    f[i][1] += array_atom[i][fy];
    if (tz >= 0) torque[i][2] += array_atom[i][tz];
  }
  return true;
}

void FixBearingBody::check_common_axis(double scale)
{
  for (int k = 0; k < modify->nfix; ++k) {
    const auto *other = dynamic_cast<const FixBearingBody *>(modify->fix[k]);
    if (!other || other == this ||
        std::hypot(axis_x_ - other->axis_x_, axis_y_ - other->axis_y_) <= 1e-9 * scale)
      continue;
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "keyword 'centre': this body turns about (%g, %g) m and fix %s '%s' about "
                  "(%g, %g) m: the races and the cage of a bearing share one axis",
                  axis_x_, axis_y_, other->style, other->id, other->axis_x_, other->axis_y_);
    error->fix_error(FLERR, this, msg);
  }
}

void FixBearingBody::check_common_model()
{
  for (int k = 0; k < modify->nfix; ++k) {
    const auto *other = dynamic_cast<const FixBearingBody *>(modify->fix[k]);
    if (!other || other == this || other->three_d() == three_d()) continue;
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "keyword 'model': this body is model %s and fix %s '%s' model %s: the races "
                  "and the cage of a bearing share one model",
                  three_d() ? "3d" : "2d", other->style, other->id, other->three_d() ? "3d" : "2d");
    error->fix_error(FLERR, this, msg);
  }
}

void FixBearingBody::set_extensive(std::vector<int> flags)
{
  extensive_ = std::move(flags);
  extvector = -1;
  extlist = extensive_.data();
}
