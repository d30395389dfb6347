// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/cage, model 3d: cylindrical pockets (contact/
   cage_contact_3d.h) and the cage free along the bearing axis, pushed by the
   balls only (it floats on them, as a ball-guided cage does). The rotation
   is integrated by fix_bearing_cage.cpp as in model 2d.
------------------------------------------------------------------------- */

#include <mpi.h>

#include <cmath>
#include <vector>

#include "BEARING/fix_bearing_cage.h"
#include "atom.h"
#include "comm.h"
#include "contact/cage_contact_3d.h"
#include "fix_property_atom.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
// The planar cage's per-ball state (pocket, pocket force, its x and y), then its z.
enum Col3 { POCKET, FORCE, FX, FY, FZ };
}  // namespace

void FixBearingCage::post_force_3d()
{
  array_atom = state_->array_atom;
  double **x = atom->x, **v = atom->v, **f = atom->f;
  ohmdem::CageContactState3d s;
  s.centre = {cx_, cy_, cz_};
  s.cage_omega = omega_;
  s.cage_vz = vz_;
  const double cos_cage = std::cos(angle_ + angle0_), sin_cage = std::sin(angle_ + angle0_);
  mine_.clear();
  int masked = 0;
  if (!defects_.empty()) defect_surface_ = surface();
  mine_axial_.clear();
  for (int i = 0; i < atom->nlocal; ++i) {
    double *out = array_atom[i];
    if (!(atom->mask[i] & groupbit)) continue;
    out[FORCE] = out[FX] = out[FY] = out[FZ] = 0.0;
    const int k = static_cast<int>(out[POCKET]);
    s.ball_x = {x[i][0], x[i][1], x[i][2]};
    s.ball_v = {v[i][0], v[i][1], v[i][2]};
    s.ball_mass = atom->rmass[i];
    s.pocket_dir = {cos_cage * pocket_cos_[k] - sin_cage * pocket_sin_[k],
                    sin_cage * pocket_cos_[k] + cos_cage * pocket_sin_[k]};
    const auto c = ohmdem::cage_contact_3d(*model_, s);
    const double rx = x[i][0] - cx_, ry = x[i][1] - cy_;
    const double r2 = rx * rx + ry * ry;
    const double orbit = r2 > 0.0 ? (rx * v[i][1] - ry * v[i][0]) / r2 : 0.0;
    auto &rec = mine_.emplace_back();
    rec.tag = atom->tag[i];
    rec.v = {0.0, 0.0, orbit};
    if (!c.touching) continue;
    auto &rec_axial = mine_axial_.emplace_back();
    rec_axial.tag = atom->tag[i];
    rec_axial.v = {0.0};
    if (!defects_.empty() && wall_broken(defect_surface_, k, c.offset > 0.0 ? 1 : -1)) {
      ++masked;
      continue;
    }
    f[i][0] += c.force_on_ball.x;
    f[i][1] += c.force_on_ball.y;
    f[i][2] += c.force_on_ball.z;
    out[FORCE] = c.offset > 0.0 ? -c.fn : c.fn;
    out[FX] = c.force_on_ball.x;
    out[FY] = c.force_on_ball.y;
    out[FZ] = c.force_on_ball.z;
    rec.v[0] = c.fn;
    rec.v[1] = c.torque_on_cage;
    rec_axial.v[0] = c.axial_on_cage;
  }
  nmasked_ = masked;
  if (!defects_.empty() && comm->nprocs > 1)
    MPI_Allreduce(&masked, &nmasked_, 1, MPI_INT, MPI_SUM, world);
  const auto &all = gather_.gather(mine_, world);
  const auto sum = ohmdem::ordered_sum<3>(all);
  sum_fn_ = sum[0];
  torque_ = sum[1];
  ball_orbit_ = all.empty() ? 0.0 : sum[2] / static_cast<double>(all.size());
  ncontacts_ = 0;
  max_fn_ = 0.0;
  for (const auto &r : all) {
    if (r.v[0] > 0.0) ++ncontacts_;
    max_fn_ = std::max(max_fn_, r.v[0]);
  }
  // The axial force on the cage, summed in tag order as the others.
  axial_ = ohmdem::ordered_sum<1>(gather_axial_.gather(mine_axial_, world))[0];
}

void FixBearingCage::axial_half_kick_3d(double dt)
{
  vz_ += 0.5 * dt * axial_ / mass_;
}

void FixBearingCage::reapply_axial_forces_3d()
{
  double **f = atom->f, **state = state_->array_atom;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) f[i][2] += state[i][FZ];
}
