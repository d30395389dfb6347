// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/cage. Contact physics in cage_contact.{h,cpp}; this file
   parses, assigns balls to pockets, integrates the cage rotation, reduces the
   reactions in tag order (ordered_reduce.h) and handles restart.
------------------------------------------------------------------------- */

#include "BEARING/fix_bearing_cage.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "common/constants.h"
#include "contact/cage_contact.h"
#include "contact/runaway.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "support/args.h"
#include "support/global_restart.h"
#include "support/material_table.h"
#include "support/require_si.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int kVectorSize = 8;
// Per-atom state in a fix property/atom (migrates, restarts); the first kPeratomCols columns
// are this fix's per-atom output.
enum Col { POCKET, FORCE, FX, FY, NCOL };
constexpr int kPeratomCols = 2;  // pocket index, pocket force on the ball (signed, N)
}  // namespace

FixBearingCage::FixBearingCage(LAMMPS *lmp, int narg, char **arg)
    : FixBearingBody(lmp, narg, arg, kVectorSize, kPeratomCols, "bearingCage_")
{
  parse(narg, arg);
  // sums over the balls: contacts, pocket forces, torque, broken-bar contacts
  set_extensive({0, 0, 1, 1, 0, 1, 0, 1});
  if (three_d_) {
    size_vector = kVectorSize + 1;  // model 3d: the cage's axial position
    set_extensive({0, 0, 1, 1, 0, 1, 0, 1, 0});
  }
}

FixBearingCage::~FixBearingCage() = default;

void FixBearingCage::parse(int narg, char **arg)
{
  ohmdem::StyleArgs a(error, "fix bearing/cage", narg, arg, 3);
  bool have[5] = {false, false, false, false, false};
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "pockets") {
      npockets_ = a.integer(kw, "the number of pockets, an integer >= 2", 2, 100000);
      have[0] = true;
    } else if (kw == "radius") {
      pitch_radius_ = a.positive(kw, "the pitch radius of the pockets, a positive length (m)");
      have[1] = true;
    } else if (kw == "clearance") {
      clearance_ = a.non_negative(kw, "the pocket clearance per side, a length >= 0 (m)");
      have[2] = true;
    } else if (kw == "type") {
      cage_type_ = a.integer(kw, "the cage material type, an atom type 1..ntypes", 1, 1 << 30);
      have[3] = true;
    } else if (kw == "mass") {
      mass_ = a.positive(kw, "the cage mass, a positive mass (kg)");
      have[4] = true;
    } else if (kw == "inertia") {
      inertia_ = a.positive(kw, "the cage moment of inertia about its axis, > 0 (kg m^2)");
    } else if (kw == "drag") {
      drag_ = a.non_negative(kw, "a rotational drag coefficient >= 0 (N m s)");
    } else if (kw == "centre" || kw == "center") {
      cx_ = axis_x_ = a.number(kw, "two coordinates x y (m)");
      cy_ = axis_y_ = a.number(kw, "two coordinates x y (m)");
    } else if (kw == "angle") {
      angle0_ = a.number(kw, "the angular position of pocket 0 (degrees)") * ohmdem::kPi / 180.0;
    } else if (kw == "model") {
      const std::string m = a.word(kw, "2d or 3d");
      if (m != "2d" && m != "3d") a.fail(kw, "2d or 3d", m.c_str());
      three_d_ = m == "3d";
    } else {
      a.unknown(kw.c_str(), "pockets radius clearance type mass inertia drag centre angle model");
    }
  }
  const char *names[5] = {"pockets", "radius", "clearance", "type", "mass"};
  for (int k = 0; k < 5; ++k)
    if (!have[k]) a.fail(names[k], "a value: the keyword is required", "nothing");
  if (cage_type_ > atom->ntypes)
    a.fail("type", "an atom type between 1 and ntypes = " + std::to_string(atom->ntypes),
           std::to_string(cage_type_).c_str());
  // A thin ring at the pitch radius unless given.
  if (inertia_ <= 0.0) inertia_ = mass_ * pitch_radius_ * pitch_radius_;
  for (int k = 0; k < npockets_; ++k) {
    pocket_cos_.push_back(std::cos(2.0 * ohmdem::kPi * k / npockets_));
    pocket_sin_.push_back(std::sin(2.0 * ohmdem::kPi * k / npockets_));
  }
}

void FixBearingCage::post_create()
{
  // Which pocket each ball sits in (fixed at the first run; -1 = not yet) and the last
  // pocket force.
  if (three_d_)
    create_state({"-1.", "0.", "0.", "0.", "0."});  // POCKET, FORCE, FX, FY, FZ
  else
    create_state({"-1.", "0.", "0.", "0."});  // POCKET, FORCE, FX, FY
  init();
}

void FixBearingCage::init()
{
  ohmdem::require_si_units(lmp, "fix bearing/cage");
  if (!atom->sphere_flag || !atom->rmass_flag)
    error->fix_error(FLERR, this, "requires atom_style sphere");
  find_state();
  find_defects(true);
}

void FixBearingCage::build_model()
{
  const GroupBalls g = scan_group();
  if (g.empty) error->fix_error(FLERR, this, "the fix group contains no atoms");
  const double rg = g.rmax;
  const int tg = g.tmax;
  const ohmdem::MaterialTable mat(lmp, style, true, false);
  try {
    model_ = std::make_unique<ohmdem::CageContactModel>(rg, clearance_, mat.E_eff(tg, cage_type_),
                                                        mat.restitution(tg, cage_type_));
  } catch (const std::exception &ex) {
    error->fix_error(FLERR, this, ex.what());
  }
  check_common_axis(pitch_radius_);
  check_common_model();
  {  // the critical step of a ball on a pocket wall (reported when the contacts run away)
    double m = 0, ball = 0;
    for (int i = 0; i < atom->nlocal; ++i)
      if (atom->mask[i] & groupbit) m = std::max(m, atom->rmass[i]);
    MPI_Allreduce(&m, &ball, 1, MPI_DOUBLE, MPI_MAX, world);
    const double cage = pitch_radius_ > 0 ? inertia_ / (pitch_radius_ * pitch_radius_) : 0.0;
    const double mu = cage > 0 && ball > 0 ? cage * ball / (cage + ball) : 0.0;
    critical_step_ = ohmdem::hertz_critical_step(model_->hertz, mu, 1.0);
  }
  const double spacing = 2.0 * ohmdem::kPi * pitch_radius_ / npockets_;
  if (2.0 * (rg + clearance_) >= spacing)
    error->fix_error(FLERR, this,
                     "pockets overlap: ball diameter + 2*clearance must be smaller than the "
                     "pocket spacing 2*pi*radius/pockets");
}

// Each unassigned ball goes to the nearest pocket; two balls in one pocket is an error.
void FixBearingCage::assign_pockets()
{
  double **state = state_->array_atom;
  std::vector<ohmdem::TaggedValues<1>> mine;
  double misplaced = 0.0;  // the largest distance of a newly placed ball off its pocket (m)
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    double &pocket = state[i][POCKET];
    if (pocket < 0.0) {
      const double phi = std::atan2(atom->x[i][1] - cy_, atom->x[i][0] - cx_) - angle_ - angle0_;
      const double step = 2.0 * ohmdem::kPi / npockets_;
      const long nearest = std::lround(phi / step);
      // A ball placed off its pocket by more than the play sits on a bar.
      const double off = std::fabs(phi - static_cast<double>(nearest) * step) * pitch_radius_;
      if (off > clearance_ * (1.0 + 1e-9) + 1e-12) misplaced = std::max(misplaced, off);
      long k = ((nearest % npockets_) + npockets_) % npockets_;
      pocket = static_cast<double>(k);
    }
    mine.push_back({static_cast<std::int64_t>(atom->tag[i]), {pocket}});
  }
  double worst = 0.0;
  MPI_Allreduce(&misplaced, &worst, 1, MPI_DOUBLE, MPI_MAX, world);
  if (worst > 0.0) {
    const std::string msg = "a ball lies " + std::to_string(worst) +
                            " m (along the pitch circle) from the centre of its pocket, more "
                            "than the pocket play 'clearance' " +
                            std::to_string(clearance_) +
                            " m: it would sit on a bar; align the pockets with the balls ('angle' "
                            "in degrees, 'pockets' = the number of balls)";
    error->fix_error(FLERR, this, msg.c_str());
  }
  const auto all = ohmdem::gather_by_tag<1>(mine, world);
  if (static_cast<int>(all.size()) < npockets_ && comm->me == 0 && !warned_empty_) {
    const std::string msg = "fix bearing/cage: " + std::to_string(npockets_) + " pockets for " +
                            std::to_string(all.size()) + " balls: some pockets stay empty";
    error->warning(FLERR, msg.c_str());
  }
  warned_empty_ = true;
  std::vector<std::int64_t> owner(npockets_, -1);
  for (const auto &r : all) {
    const int k = static_cast<int>(r.v[0]);
    if (k < 0 || k >= npockets_) error->fix_error(FLERR, this, "invalid pocket index in restart");
    if (owner[k] >= 0) {
      const std::string msg = "atoms " + std::to_string(owner[k]) + " and " +
                              std::to_string(r.tag) + " are both in pocket " + std::to_string(k) +
                              ": place one ball per pocket (check 'pockets' and 'angle')";
      error->fix_error(FLERR, this, msg.c_str());
    }
    owner[k] = r.tag;
  }
}

void FixBearingCage::setup(int vflag)
{
  build_model();
  assign_pockets();
  if (three_d_ && restored_) reapply_axial_forces_3d();
  if (reapply_restored_forces(FX, FY, -1)) return;
  post_force(vflag);
}

void FixBearingCage::initial_integrate(int)
{
  const double dt = update->dt;
  omega_ += 0.5 * dt * (torque_ - drag_ * omega_) / inertia_;
  angle_ += dt * omega_;
  if (three_d_) {
    axial_half_kick_3d(dt);
    cz_ += dt * vz_;
  }
}

void FixBearingCage::final_integrate()
{
  omega_ += 0.5 * update->dt * (torque_ - drag_ * omega_) / inertia_;
  if (three_d_) axial_half_kick_3d(update->dt);
}

void FixBearingCage::post_force(int)
{
  if (three_d_) {
    post_force_3d();
    return;
  }
  array_atom = state_->array_atom;  // may have moved when atoms were exchanged
  double **x = atom->x, **v = atom->v, **f = atom->f;
  ohmdem::CageContactState s;
  s.centre = {cx_, cy_};
  s.cage_omega = omega_;
  const double cos_cage = std::cos(angle_ + angle0_), sin_cage = std::sin(angle_ + angle0_);
  mine_.clear();
  int masked = 0;
  if (!defects_.empty()) defect_surface_ = surface();  // what the defects need, once per step
  for (int i = 0; i < atom->nlocal; ++i) {
    double *out = array_atom[i];
    if (!(atom->mask[i] & groupbit)) continue;
    out[FORCE] = out[FX] = out[FY] = 0.0;
    const int k = static_cast<int>(out[POCKET]);
    s.ball_x = {x[i][0], x[i][1]};
    s.ball_v = {v[i][0], v[i][1]};
    s.ball_mass = atom->rmass[i];
    s.pocket_dir = {cos_cage * pocket_cos_[k] - sin_cage * pocket_sin_[k],
                    sin_cage * pocket_cos_[k] + cos_cage * pocket_sin_[k]};
    const auto c = ohmdem::cage_contact(*model_, s);
    const double rx = x[i][0] - cx_, ry = x[i][1] - cy_;
    const double r2 = rx * rx + ry * ry;
    const double orbit = r2 > 0.0 ? (rx * v[i][1] - ry * v[i][0]) / r2 : 0.0;
    // Built in place: a braced temporary costs a store-forwarding stall per ball.
    auto &rec = mine_.emplace_back();
    rec.tag = atom->tag[i];
    rec.v = {0.0, 0.0, orbit};
    if (!c.touching) continue;
    if (!defects_.empty() && wall_broken(defect_surface_, k, c.offset > 0.0 ? 1 : -1)) {
      ++masked;  // a broken bar: nothing to push on
      continue;
    }
    f[i][0] += c.force_on_ball.x;
    f[i][1] += c.force_on_ball.y;
    out[FORCE] = c.offset > 0.0 ? -c.fn : c.fn;
    out[FX] = c.force_on_ball.x;
    out[FY] = c.force_on_ball.y;
    rec.v[0] = c.fn;
    rec.v[1] = c.torque_on_cage;
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
}

bool FixBearingCage::wall_broken(const ohmdem::BearingSurface &surface, int pocket, int side) const
{
  for (const auto *d : defects_)
    if (d->breaks_wall(surface, pocket, side)) return true;
  return false;
}

ohmdem::BearingSurface FixBearingCage::surface() const
{
  ohmdem::BearingSurface s;
  s.body = static_cast<const ohmdem::BearingBody *>(this);
  s.kind = ohmdem::BodyKind::Cage;
  s.centre[0] = cx_;
  s.centre[1] = cy_;
  s.radius = pitch_radius_;
  s.angle = angle_;
  s.pockets = npockets_;
  return s;
}

double FixBearingCage::compute_vector(int n)
{
  switch (n) {
    case 0:
      return angle_;
    case 1:
      return omega_;
    case 2:
      return ncontacts_;
    case 3:
      return sum_fn_;
    case 4:
      return max_fn_;
    case 5:
      return torque_;
    case 6:
      return ball_orbit_;
    case 7:
      return nmasked_;
    case 8:
      return cz_;  // model 3d only
    default:
      return 0.0;
  }
}

template <class Visit> void FixBearingCage::restart_fields(Visit &record)
{
  record(angle_, omega_, npockets_, torque_, sum_fn_, max_fn_, ncontacts_, ball_orbit_);
  double marker = 3.0;
  if (three_d_) record(cz_, vz_, axial_, marker);
}

void FixBearingCage::write_restart(FILE *fp)
{
  ohmdem::RestartWriter record;
  restart_fields(record);
  record.write(comm->me, fp);
}

void FixBearingCage::restart(char *buf)
{
  ohmdem::RestartReader record(buf);
  constexpr int kPocketsSlot = 2;  // restart_fields' third value, checked before any is read
  if (static_cast<int>(record.at(kPocketsSlot)) != npockets_)
    error->fix_error(FLERR, this, "restart data has a different number of pockets");
  restart_fields(record);
  restored_ = true;
}

double FixBearingCage::memory_usage()
{
  // Per-atom state lives in the fix property/atom, which reports its own.
  return static_cast<double>(mine_.capacity() * sizeof(mine_[0]) + gather_.memory_usage() +
                             (pocket_cos_.capacity() + pocket_sin_.capacity()) * sizeof(double));
}

void *FixBearingCage::extract(const char *name, int &dim)
{
  dim = 0;
  if (std::strcmp(name, "cage_critical_step") == 0) return &critical_step_;
  if (std::strcmp(name, "cage_mass") == 0) return &mass_;
  return nullptr;
}
