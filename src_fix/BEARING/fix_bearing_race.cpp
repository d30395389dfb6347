// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/race: an analytic bearing ring with a toroidal groove.
   Contact physics lives in contact/race_contact.{h,cpp}, the arguments in
   race_settings.*, the variables they may name in race_variables.*, the checks
   that stop a run in race_checks.*; this file integrates the ring's own degrees
   of freedom, reduces reactions and handles restart.
------------------------------------------------------------------------- */

#include "BEARING/fix_bearing_race.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "atom.h"
#include "comm.h"
#include "contact/race_contact.h"
#include "contact/race_contact_3d.h"  // model3d_ (fix_bearing_race_3d.cpp)
#include "contact/runaway.h"
#include "error.h"
#include "fix_property_atom.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "support/global_restart.h"
#include "support/material_table.h"
#include "support/require_si.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using ohmdem::RaceContactModel;

namespace {
// The global vector (doc/fix_bearing_race.md, "Output info"): compute_vector(n) is f_ID[n+1].
namespace out {
enum Vector {
  SUM_FN,        // total normal force of the balls on the ring
  TORQUE,        // their torque about z
  INTERFERENCE,  // u
  CENTRE_X,
  CENTRE_Y,
  LOADED,        // contacts carrying a load
  MEAN_FN,
  MAX_FN,
  ANGLE,
  OMEGA,
  MASKED,  // contacts in a defect zone
  VEL_ALONG,
  VEL_ACROSS,
  ACC_ALONG,
  ACC_ACROSS,
  PLANAR_VECTOR,               // the values of model 2d; model 3d adds compute_vector_3d's
  VECTOR_3D = PLANAR_VECTOR + 8
};
}  // namespace out
// Per-atom state, kept in a fix property/atom so that it migrates with the atom and goes to
// restart files. The first kPeratomCols columns are this fix's per-atom output, the contact
// that the electrical computes read through RaceContactView; the rest is private state.
using View = ohmdem::RaceContactView;
enum Col {
  FN = View::kFn,
  DELTA = View::kDelta,
  FT = View::kFt,
  PX = View::kPointX,
  PY = View::kPointY,
  MASKED = View::kInDefect,
  FX = View::kColumns,
  FY,
  TZ,
  SHEAR,
  NCOL
};
constexpr int kPeratomCols = View::kColumns;  // fn, delta, ft, contact point x, y, masked
}  // namespace

FixBearingRace::FixBearingRace(LAMMPS *lmp, int narg, char **arg)
    : FixBearingBody(lmp, narg, arg, out::PLANAR_VECTOR, kPeratomCols, "bearingRace_"),
      settings_(ohmdem::parse_race_settings(error, narg, arg, atom->ntypes)),
      variables_(lmp, this, settings_.omega_var, settings_.force_var),
      load_force_(settings_.load_force),
      load_fx_(settings_.load_fx),
      load_fy_(settings_.load_fy)
{
  cx_ = axis_x_ = settings_.centre_x;
  cy_ = axis_y_ = settings_.centre_y;
  if (settings_.load == Load::Fixed) u_ = settings_.interference;
  // sums over the balls: total normal force, torque, contacts, masked contacts
  std::vector<int> extensive(out::PLANAR_VECTOR, 0);
  for (int n : {out::SUM_FN, out::TORQUE, out::LOADED, out::MASKED}) extensive[n] = 1;
  set_extensive(extensive);
  if (three_d()) {
    // model 3d: 8 more values (the balls' axial force and moment are sums), 2 more columns.
    size_vector = out::VECTOR_3D;
    size_peratom_cols = View::kColumns3d;
    extensive.resize(out::VECTOR_3D, 0);
    extensive[out::PLANAR_VECTOR + 6] = extensive[out::PLANAR_VECTOR + 7] = 1;
    set_extensive(extensive);
    if (settings_.model3d.preload_set) cz_ = settings_.model3d.preload;
  }
}

FixBearingRace::~FixBearingRace() = default;

void FixBearingRace::post_create()
{
  // Per-ball contact state: the contact, the last forces, the tangential spring history.
  create_state(std::vector<std::string>(three_d() ? state_columns_3d() : NCOL, "0."));
  init();
}

void FixBearingRace::init()
{
  ohmdem::require_si_units(lmp, "fix bearing/race");
  if (!atom->sphere_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->fix_error(FLERR, this, "requires atom_style sphere (radius, rmass, omega, torque)");
  find_state();
  find_defects(false);  // only the defects that can touch a race contact
  // a cage's critical step, through the generic Fix interface (no header of the cage)
  cage_step_ = cage_mass_ = nullptr;
  for (int i = 0; i < modify->nfix && !cage_step_; ++i) {
    int dim = 0;
    cage_step_ = static_cast<const double *>(modify->fix[i]->extract("cage_critical_step", dim));
    cage_mass_ = static_cast<const double *>(modify->fix[i]->extract("cage_mass", dim));
  }
}

// Ball type and radius of the group, the materials, and the Hertz model built from them.
void FixBearingRace::build_model()
{
  const GroupBalls g = scan_group();
  if (g.empty) error->fix_error(FLERR, this, "the fix group contains no atoms");
  if (g.rmax - g.rmin > 1e-12 * g.rmax)
    error->fix_error(FLERR, this, "all balls of the group must have the same radius");
  if (g.tmin != g.tmax)
    error->fix_error(FLERR, this, "all balls of the group must have the same atom type");
  ball_radius_ = g.rmax;
  ball_type_ = g.tmin;
  double m = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) m = std::max(m, atom->rmass[i]);
  MPI_Allreduce(&m, &ball_mass_, 1, MPI_DOUBLE, MPI_MAX, world);

  const ohmdem::MaterialTable mat(lmp, style, true, true);
  const ohmdem::RaceSettings &s = settings_;
  const int t = s.race_type;
  try {
    model_ = std::make_unique<RaceContactModel>(
        s.inner ? ohmdem::RaceSide::Inner : ohmdem::RaceSide::Outer, ball_radius_, s.radius,
        s.groove, mat.E_eff(ball_type_, t), mat.G_eff(ball_type_, t),
        mat.restitution(ball_type_, t), mat.friction(ball_type_, t));
  } catch (const std::exception &ex) {
    const std::string msg = std::string("invalid race: ") + ex.what() + " (ball radius " +
                            std::to_string(ball_radius_) + " m, groove " +
                            std::to_string(s.groove) + " m, race radius " +
                            std::to_string(s.radius) + " m)";
    error->fix_error(FLERR, this, msg.c_str());
  }

  const std::string overload = ohmdem::load_beyond_elastic_range(
      s.load, load_force_, group->count(igroup), model_->hertz, ball_radius_);
  if (!overload.empty()) error->fix_error(FLERR, this, overload.c_str());
  check_common_axis(s.radius);
  check_common_model();
  check_fit_between_races();
}

// Balls must fit between an inner and an outer race of the same bearing.
void FixBearingRace::check_fit_between_races()
{
  for (int k = 0; k < modify->nfix; ++k) {
    auto *other = dynamic_cast<FixBearingRace *>(modify->fix[k]);
    if (!other || other == this || other->settings_.inner == settings_.inner) continue;
    const FixBearingRace &in = settings_.inner ? *this : *other,
                         &out = settings_.inner ? *other : *this;
    const std::string why =
        ohmdem::balls_do_not_fit(in.settings_.radius, out.settings_.radius, ball_radius_);
    if (!why.empty()) error->fix_error(FLERR, this, why.c_str());
  }
}

void FixBearingRace::setup(int vflag)
{
  variables_.find();
  evaluate_variables();
  build_model();
  if (three_d()) build_model_3d();
  if (restored_ && !three_d()) {  // model 3d: its own check, in build_model_3d
    const double gap =
        ohmdem::worst_ball_gap(*atom, groupbit, settings_.inner, cx_, cy_, current_radius(), world);
    const std::string why = ohmdem::restart_geometry_changed(gap, settings_.radius, ball_radius_);
    if (!why.empty()) error->fix_error(FLERR, this, why.c_str());
  }
  if (three_d() ? reapply_restored_forces_3d() : reapply_restored_forces(FX, FY, TZ)) {
    // the loaded contacts of the restored step, from the restored per-ball normal forces
    int mine = 0;
    for (int i = 0; i < atom->nlocal; ++i)
      if ((atom->mask[i] & groupbit) && array_atom[i][FN] > 0.0) ++mine;
    MPI_Allreduce(&mine, &loaded_, 1, MPI_INT, MPI_SUM, world);
    return;
  }
  post_force(vflag);
}

double FixBearingRace::target_omega(double t) const
{
  const ohmdem::RaceSettings &s = settings_;
  if (variables_.sets_omega()) return omega_now_;
  if (s.ramp > 0.0 && t < s.ramp) return s.omega_start + (s.omega - s.omega_start) * t / s.ramp;
  return s.omega;
}

// The values of this step of the variables omega/force may name.
void FixBearingRace::evaluate_variables()
{
  if (!variables_.any()) return;
  variables_.evaluate(omega_now_, load_force_);
  if (variables_.sets_force() && settings_.load == Load::Radial) {
    load_fx_ = load_force_ * settings_.dir_ux;
    load_fy_ = load_force_ * settings_.dir_uy;
  }
}

double FixBearingRace::current_radius() const
{
  return settings_.inner ? settings_.radius + u_ : settings_.radius - u_;
}

ohmdem::BearingSurface FixBearingRace::surface() const
{
  ohmdem::BearingSurface s;
  s.body = static_cast<const ohmdem::BearingBody *>(this);
  s.kind = settings_.inner ? ohmdem::BodyKind::InnerRace : ohmdem::BodyKind::OuterRace;
  s.centre[0] = cx_;
  s.centre[1] = cy_;
  s.radius = current_radius();
  s.angle = angle_;
  s.ball_radius = model_ ? model_->ball_radius : ball_radius_;
  s.groove = settings_.groove;
  s.three_d = three_d();
  return s;
}

// Half a velocity-Verlet kick of the ring's free degrees of freedom.
void FixBearingRace::ring_half_kick(double dt)
{
  const double h = 0.5 * dt;
  const Load load = settings_.load;
  const double mass = settings_.ring_mass, damp = settings_.ring_damp;
  if ((load == Load::Force || load == Load::Settle) && !frozen_) {
    u_dot_ += h * (load_force_ - sum_fn_ - damp * u_dot_) / mass;
  } else if (load == Load::Radial) {
    // The balls push the ring with the opposite of the forces the ring puts on them.
    vcx_ += h * (load_fx_ - fx_ - damp * vcx_) / mass;
    vcy_ += h * (load_fy_ - fy_ - damp * vcy_) / mass;
  }
}

// The ring centre's acceleration at the end of the step: Newton's law with the forces of this
// step and the velocity reached (zero unless the centre is free, load radial).
void FixBearingRace::ring_acceleration(double &ax, double &ay) const
{
  ax = ay = 0.0;
  double lx = load_fx_, ly = load_fy_;
  if (settings_.on_housing())
    housing_force(lx, ly);  // model 3d: the outer ring on its housing
  else if (settings_.load != Load::Radial)
    return;
  const double mass = settings_.ring_mass, damp = settings_.ring_damp;
  ax = (lx - fx_ - damp * vcx_) / mass;
  ay = (ly - fy_ - damp * vcy_) / mass;
}

void FixBearingRace::initial_integrate(int)
{
  if (three_d()) {
    initial_integrate_3d();
    return;
  }
  const double dt = update->dt;
  evaluate_variables();
  ring_half_kick(dt);
  angle_ += dt * target_omega(time_ + 0.5 * dt);
  u_ += dt * u_dot_;
  cx_ += dt * vcx_;
  cy_ += dt * vcy_;
  time_ += dt;
  if (settings_.load == Load::Settle && !frozen_ && time_ >= settings_.settle_time) {
    frozen_ = true;  // displacement control from now on, at the radius reached under F
    u_dot_ = 0.0;
  }
}

void FixBearingRace::final_integrate()
{
  if (three_d()) {
    ring_half_kick_3d(update->dt);
    return;
  }
  ring_half_kick(update->dt);
}

void FixBearingRace::post_force(int)
{
  if (three_d()) {
    post_force_3d();
    return;
  }
  array_atom = state_->array_atom;  // may have moved when atoms were exchanged
  double **x = atom->x, **v = atom->v, **f = atom->f, **omega = atom->omega;
  double **torque = atom->torque;
  const int nlocal = atom->nlocal;
  const bool update_history = !update->setupflag;
  const double dt = update->dt;

  ohmdem::RaceContactState s;
  s.race_centre = {cx_, cy_};
  s.race_v = {vcx_, vcy_};
  s.race_radius = current_radius();
  s.race_radius_rate = u_dot_;
  s.race_omega = target_omega(time_);

  mine_.clear();
  int masked = 0;
  if (!defects_.empty()) defect_surface_ = surface();  // what the defects need, once per step
  for (int i = 0; i < nlocal; ++i) {
    double *out = array_atom[i];
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k = FN; k <= TZ; ++k) out[k] = 0.0;
    s.recess = 0.0;
    if (!defects_.empty()) {
      bool in_zone = false;
      s.recess = defect_recess(i, defect_surface_, in_zone);
      out[MASKED] = in_zone ? 1.0 : 0.0;
      masked += in_zone;
    }
    s.ball_x = {x[i][0], x[i][1]};
    s.ball_v = {v[i][0], v[i][1]};
    s.ball_omega = omega[i][2];
    s.ball_mass = atom->rmass[i];
    const auto c = ohmdem::race_contact(*model_, s, dt, update_history, out[SHEAR]);
    if (!c.touching) continue;
    f[i][0] += c.force_on_ball.x;
    f[i][1] += c.force_on_ball.y;
    torque[i][2] += c.torque_on_ball;
    out[FN] = c.fn;
    out[DELTA] = c.delta;
    out[FT] = c.ft;
    out[PX] = c.point.x;
    out[PY] = c.point.y;
    out[FX] = c.force_on_ball.x;
    out[FY] = c.force_on_ball.y;
    out[TZ] = c.torque_on_ball;
    // Built in place: a braced temporary costs a store-forwarding stall per ball.
    auto &rec = mine_.emplace_back();
    rec.tag = atom->tag[i];
    rec.v = {c.force_on_ball.x, c.force_on_ball.y, c.fn, c.torque_on_race};
  }
  nmasked_ = masked;
  if (!defects_.empty() && comm->nprocs > 1)
    MPI_Allreduce(&masked, &nmasked_, 1, MPI_INT, MPI_SUM, world);
  const auto &all = gather_.gather(mine_, world);
  const auto sum = ohmdem::ordered_sum<4>(all);
  fx_ = sum[0];
  fy_ = sum[1];
  sum_fn_ = sum[2];
  torque_ = sum[3];
  ncontacts_ = static_cast<int>(all.size());
  loaded_ = 0;  // touching with a load: a ball exactly touching (fn = 0) carries nothing
  for (const auto &r : all) loaded_ += r.v[2] > 0.0;
  max_fn_ = 0.0;
  for (const auto &r : all) max_fn_ = std::max(max_fn_, r.v[2]);
  check_runaway();
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
  const Load load = settings_.load;
  s.ring_mass = load == Load::None || load == Load::Fixed ? 0.0 : settings_.ring_mass;
  s.ring_damping = settings_.ring_damp;
  s.balls = ncontacts_;
  s.cage_step = cage_step_ ? *cage_step_ : 0.0;
  s.cage_mass = cage_mass_ ? *cage_mass_ : 0.0;
  const std::string why = ohmdem::runaway(model_->hertz, runaway_, s);
  if (!why.empty()) error->fix_error(FLERR, this, why.c_str());
}

// Sum of the recesses of the defects under ball i's contact with this race; in_zone is set
// when the contact point lies in a defect zone (the contact then carries no current).
double FixBearingRace::defect_recess(int i, const ohmdem::BearingSurface &surface,
                                     bool &in_zone) const
{
  // The contact lies on the line from the race centre to the ball centre.
  const double dx = atom->x[i][0] - cx_, dy = atom->x[i][1] - cy_;
  double recess = 0.0;
  for (const auto *d : defects_) recess += d->recess(surface, atom->tag[i], dx, dy, in_zone);
  return recess;
}

bool FixBearingRace::defect_pit(int i, double reach, ohmdem::PitView &pit, double &rest) const
{
  const double dx = atom->x[i][0] - cx_, dy = atom->x[i][1] - cy_;  // as defect_recess
  // model 3d: where across the groove the contact lies (the _at queries of a planar race are
  // the plain ones)
  const double alpha = three_d() ? contact_angle_3d(i, ring_motion_3d()) : 0.0;
  bool found = false, in_zone = false;
  for (const auto *d : defects_) {
    if (!found && d->pit_near_at(defect_surface_, dx, dy, alpha, reach, pit))
      found = true;
    else
      rest += d->recess_at(defect_surface_, atom->tag[i], dx, dy, alpha, in_zone);
  }
  return found;
}

double FixBearingRace::compute_vector(int n)
{
  if (n >= out::PLANAR_VECTOR) return compute_vector_3d(n - out::PLANAR_VECTOR);
  // The vibration channel: centre velocity and acceleration along the load direction and
  // across it (the direction turned +90 degrees about z).
  const double ux = settings_.dir_ux, uy = settings_.dir_uy;
  double ax = 0.0, ay = 0.0;
  if (n == out::ACC_ALONG || n == out::ACC_ACROSS) ring_acceleration(ax, ay);
  switch (static_cast<out::Vector>(n)) {
    case out::SUM_FN:
      return sum_fn_;
    case out::TORQUE:
      return torque_;
    case out::INTERFERENCE:
      return u_;
    case out::CENTRE_X:
      return cx_;
    case out::CENTRE_Y:
      return cy_;
    case out::LOADED:
      return loaded_;
    case out::MEAN_FN:
      return ncontacts_ ? sum_fn_ / ncontacts_ : 0.0;
    case out::MAX_FN:
      return max_fn_;
    case out::ANGLE:
      return angle_;
    case out::OMEGA:
      return target_omega(time_);
    case out::MASKED:
      return nmasked_;
    case out::VEL_ALONG:
      return vcx_ * ux + vcy_ * uy;
    case out::VEL_ACROSS:
      return -vcx_ * uy + vcy_ * ux;
    case out::ACC_ALONG:
      return ax * ux + ay * uy;
    case out::ACC_ACROSS:
      return -ax * uy + ay * ux;
    default:
      return 0.0;
  }
}

template <class Visit> void FixBearingRace::restart_fields(Visit &record, double &side)
{
  record(time_, angle_, u_, u_dot_, cx_, cy_, vcx_, vcy_, frozen_, side, sum_fn_, torque_, fx_,
         fy_, max_fn_, ncontacts_, nmasked_);
  if (three_d())
    record(cz_, vcz_, tilt_[0], tilt_[1], tilt_rate_[0], tilt_rate_[1], fz_, moment_[0],
           moment_[1], radial_sum_, alpha_mean_, alpha_max_);
}

void FixBearingRace::write_restart(FILE *fp)
{
  ohmdem::RestartWriter record;
  double side = side_code();
  restart_fields(record, side);
  record.write(comm->me, fp);
}

void FixBearingRace::restart(char *buf)
{
  ohmdem::RestartReader record(buf);
  constexpr int kSideSlot = 9;  // restart_fields' tenth value, read before any other
  const double side = record.at(kSideSlot);
  if ((side > 1.5) != three_d())
    error->fix_error(FLERR, this,
                     three_d() ? "restart data is of model 2d: a run continues with the model "
                                 "it was written with"
                               : "restart data is of model 3d: a run continues with the model "
                                 "it was written with");
  if ((side == 1.0 || side == 3.0) != settings_.inner)
    error->fix_error(FLERR, this, "restart data is for the other race side (inner/outer)");
  double read_side = 0.0;
  restart_fields(record, read_side);
  restored_ = true;
}

double FixBearingRace::memory_usage()
{
  // Per-atom state lives in the fix property/atom, which reports its own.
  return static_cast<double>(mine_.capacity() * sizeof(mine_[0]) + gather_.memory_usage() +
                             mine3d_.capacity() * sizeof(mine3d_[0]) + gather3d_.memory_usage());
}
