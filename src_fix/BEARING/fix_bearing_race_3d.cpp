// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/race, model 3d: the race as the torus swept by its
   groove's curvature-centre circle (contact/torus_race.h), the balls free in
   space, the ring a rigid body whose centre moves in space and whose axis
   tilts under load radial (force along direction, axial, moment, or an axial
   position held by preload). The contact physics is contact/race_contact_3d.h;
   this file integrates the ring and reduces the reactions in tag order;
   restart_fields (fix_bearing_race.cpp) holds both models' restart record.
   doc/fix_bearing_race.md ("Model 3d"), doc/methods/bearing_3d.md.
------------------------------------------------------------------------- */

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "atom.h"
#include "comm.h"
#include "common/constants.h"
#include "contact/race_contact.h"
#include "contact/race_contact_3d.h"
#include "contact/race_grooves.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"
#include "support/material_table.h"
#include "update.h"

using namespace LAMMPS_NS;
using ohmdem::Vec3;

namespace {
using View = ohmdem::RaceContactView;
// Per-ball state of model 3d in the fix property/atom: the published columns first (those of
// model 2d, then the contact point's z and the signed contact angle in degrees), then cos(alpha)
// of the contact, the forces of this step on the ball and its torque (for a restart), the
// tangential spring and the twist of the torsional spring.
enum Col3 {
  FN = View::kFn,
  DELTA = View::kDelta,
  FT = View::kFt,
  PX = View::kPointX,
  PY = View::kPointY,
  MASKED = View::kInDefect,
  PZ = View::kPointZ,
  ALPHA = View::kAngle,
  COSA = View::kColumns3d,
  FX,
  FY,
  FZ,
  TX,
  TY,
  TZ,
  SHX,
  SHY,
  SHZ,
  TWIST,
  ROLL,  // the film's entrainment speed (m/s)
  NCOL3
};
// Per touching ball, summed in tag order: its force (3), normal force, the torque on the ring
// (3), |alpha| (deg), Q cos(alpha), |alpha| plus the ellipse's half-width across the groove
// (deg), and 1 if it touches past the groove's circle.
enum Rec { RFX, RFY, RFZ, RFN, RTX, RTY, RTZ, RALPHA, RRADIAL, REDGE, ROFF, NREC };
}  // namespace

int FixBearingRace::state_columns_3d()
{
  return NCOL3;
}

void FixBearingRace::build_model_3d()
{
  const ohmdem::RaceSettings &s = settings_;
  const ohmdem::RaceSettings::Model3d &m3 = s.model3d;
  const ohmdem::MaterialTable mat(lmp, style, true, true);
  const int t = s.race_type, b = ball_type_;
  const ohmdem::RaceSide side = s.inner ? ohmdem::RaceSide::Inner : ohmdem::RaceSide::Outer;
  try {
    const ohmdem::GrooveCircle c =
        ohmdem::groove_circle(side, s.radius, s.groove, ball_radius_, m3.clearance, m3.alpha0);
    ohmdem::TorusGroove g;
    g.side = side;
    g.ball_radius = ball_radius_;
    g.groove_radius = s.groove;
    g.centre_radius = c.centre_radius;
    g.centre_z = c.centre_z;
    model3d_ = std::make_unique<ohmdem::RaceContactModel3d>(
        g, mat.E_eff(b, t), mat.G_eff(b, t),
        ohmdem::torsion_shear_modulus(mat.E(b), mat.nu(b), mat.E(t), mat.nu(t)),
        mat.restitution(b, t), mat.friction(b, t));
  } catch (const std::exception &ex) {
    error->fix_error(FLERR, this, (std::string("invalid 3D race: ") + ex.what()).c_str());
  }
  const double r2 = s.radius * s.radius;
  tilt_inertia_ = m3.tilt_inertia > 0.0 ? m3.tilt_inertia : 0.5 * s.ring_mass * r2;
  tilt_damp_ = m3.tilt_damp >= 0.0 ? m3.tilt_damp : 0.5 * s.ring_damp * r2;

  // With the other race: one clearance and one nominal angle, a play the grooves can hold.
  other_race_ = nullptr;
  for (int k = 0; k < modify->nfix; ++k) {
    auto *other = dynamic_cast<FixBearingRace *>(modify->fix[k]);
    if (!other || other == this || other->settings_.inner == s.inner) continue;
    other_race_ = other;
    const ohmdem::RaceSettings::Model3d &o3 = other->settings_.model3d;
    if (o3.clearance != m3.clearance || o3.alpha0 != m3.alpha0)
      error->fix_error(FLERR, this,
                       "keywords 'clearance' and 'alpha0': the two races of a bearing take the "
                       "same values (the bearing's clearance and nominal contact angle)");
    const ohmdem::RaceSettings &in = s.inner ? s : other->settings_;
    const ohmdem::RaceSettings &out = s.inner ? other->settings_ : s;
    const double base = 2.0 * (out.radius - in.radius - 2.0 * ball_radius_);  // diametral
    if (m3.alpha0 > 0.0 && std::fabs(base) > 1e-9 * out.radius)
      error->fix_error(FLERR, this,
                       ("keyword 'alpha0': the angular-contact grooves are built on races with no "
                        "diametral clearance of their own (outer - inner radius = ball diameter), "
                        "got " +
                        std::to_string(base) + " m")
                           .c_str());
    const double A = in.groove + out.groove - 2.0 * ball_radius_;
    double free_angle = m3.alpha0;
    try {
      if (m3.alpha0 == 0.0) free_angle = ohmdem::free_contact_angle(base + m3.clearance, A);
    } catch (const std::exception &ex) {
      error->fix_error(FLERR, this, (std::string("keyword 'clearance': ") + ex.what()).c_str());
    }
    const double shoulder = std::min(m3.shoulder, o3.shoulder);
    if (free_angle >= shoulder) {
      char msg[512];
      std::snprintf(msg, sizeof msg,
                    "keyword 'clearance': the free contact angle %g deg of a clearance of %g m "
                    "reaches the shoulder at %g deg: the balls would leave the groove",
                    free_angle / ohmdem::kDegree, base + m3.clearance, shoulder / ohmdem::kDegree);
      error->fix_error(FLERR, this, msg);
    }
  }
}

ohmdem::RingMotion3d FixBearingRace::ring_motion_3d() const
{
  ohmdem::RingMotion3d r;
  r.centre = {cx_, cy_, cz_};
  r.tilt = ohmdem::rotation_vector({tilt_[0], tilt_[1], 0.0});
  r.tilted = tilt_[0] != 0.0 || tilt_[1] != 0.0;
  r.velocity = {vcx_, vcy_, vcz_};
  r.omega = target_omega(time_) * r.tilt.column(2) + Vec3{tilt_rate_[0], tilt_rate_[1], 0.0};
  r.radius_shift = u_;
  r.radius_rate = u_dot_;
  return r;
}

void FixBearingRace::post_force_3d()
{
  array_atom = state_->array_atom;  // may have moved when atoms were exchanged
  double **x = atom->x, **v = atom->v, **f = atom->f, **omega = atom->omega;
  double **torque = atom->torque;
  const int nlocal = atom->nlocal;
  const bool update_history = !update->setupflag;
  const double dt = update->dt;
  const ohmdem::RingMotion3d ring = ring_motion_3d();
  const double shoulder = settings_.model3d.shoulder;
  const double groove = settings_.groove;

  mine3d_.clear();
  int masked = 0;
  if (!defects_.empty()) defect_surface_ = surface();
  for (int i = 0; i < nlocal; ++i) {
    double *out = array_atom[i];
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k : {FN, DELTA, FT, PX, PY, PZ, ALPHA, FX, FY, FZ, TX, TY, TZ, ROLL}) out[k] = 0.0;
    out[COSA] = 1.0;
    double recess = 0.0;
    if (!defects_.empty()) {
      // Where across the groove the contact lies: its contact angle before the recess.
      bool in_zone = false;
      recess = defect_recess_3d(i, contact_angle_3d(i, ring), in_zone);
      out[MASKED] = in_zone ? 1.0 : 0.0;
      masked += in_zone;
    }
    ohmdem::BallState3d b;
    b.x = {x[i][0], x[i][1], x[i][2]};
    b.v = {v[i][0], v[i][1], v[i][2]};
    b.omega = {omega[i][0], omega[i][1], omega[i][2]};
    b.mass = atom->rmass[i];
    b.inertia = 0.4 * b.mass * atom->radius[i] * atom->radius[i];
    const auto c = ohmdem::race_contact_3d(*model3d_, ring, b, recess, dt, update_history,
                                           {&out[SHX], &out[TWIST]});
    if (!c.touching) continue;
    auto &rec = mine3d_.emplace_back();
    rec.tag = atom->tag[i];
    rec.v.fill(0.0);
    if (c.off_groove) {
      rec.v[ROFF] = 1.0;
      continue;
    }
    f[i][0] += c.force_on_ball.x;
    f[i][1] += c.force_on_ball.y;
    f[i][2] += c.force_on_ball.z;
    torque[i][0] += c.torque_on_ball.x;
    torque[i][1] += c.torque_on_ball.y;
    torque[i][2] += c.torque_on_ball.z;
    const double alpha = std::atan2(c.sin_alpha, c.cos_alpha) / ohmdem::kDegree;
    out[FN] = c.fn;
    out[DELTA] = c.delta;
    out[FT] = c.ft_rolling;
    out[PX] = c.point.x;
    out[PY] = c.point.y;
    out[PZ] = c.point.z;
    out[ALPHA] = alpha;
    out[COSA] = c.cos_alpha;
    out[FX] = c.force_on_ball.x;
    out[FY] = c.force_on_ball.y;
    out[FZ] = c.force_on_ball.z;
    out[TX] = c.torque_on_ball.x;
    out[TY] = c.torque_on_ball.y;
    out[TZ] = c.torque_on_ball.z;
    out[ROLL] = c.rolling_speed;
    rec.v = {c.force_on_ball.x,
             c.force_on_ball.y,
             c.force_on_ball.z,
             c.fn,
             c.torque_on_ring.x,
             c.torque_on_ring.y,
             c.torque_on_ring.z,
             std::fabs(alpha),
             c.fn * c.cos_alpha,
             std::fabs(alpha),
             0.0};
    if (shoulder < 0.5 * ohmdem::kPi) {
      // The ellipse's major half-axis lies across the groove: a / Rc of its arc.
      const double a = model3d_->hertz.ellipse(c.cos_alpha, c.fn, ohmdem::AreaModel::Exact).a;
      rec.v[REDGE] += a / groove / ohmdem::kDegree;
    }
  }
  nmasked_ = masked;
  if (!defects_.empty() && comm->nprocs > 1)
    MPI_Allreduce(&masked, &nmasked_, 1, MPI_INT, MPI_SUM, world);
  const auto &all = gather3d_.gather(mine3d_, world);
  const auto sum = ohmdem::ordered_sum<NREC>(all);
  fx_ = sum[RFX];
  fy_ = sum[RFY];
  fz_ = sum[RFZ];
  sum_fn_ = sum[RFN];
  moment_[0] = sum[RTX];
  moment_[1] = sum[RTY];
  torque_ = sum[RTZ];
  radial_sum_ = sum[RRADIAL];
  ncontacts_ = static_cast<int>(all.size()) - static_cast<int>(sum[ROFF]);
  alpha_mean_ = ncontacts_ > 0 ? sum[RALPHA] / ncontacts_ : 0.0;
  max_fn_ = alpha_max_ = 0.0;
  loaded_ = 0;  // touching with a load: a ball exactly touching (fn = 0) carries nothing
  double edge = 0.0;
  for (const auto &r : all) {
    loaded_ += r.v[RFN] > 0.0;
    max_fn_ = std::max(max_fn_, r.v[RFN]);
    alpha_max_ = std::max(alpha_max_, r.v[RALPHA]);
    edge = std::max(edge, r.v[REDGE]);
  }
  if (sum[ROFF] > 0.0) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "at t = %g s %d ball(s) touch this race past its groove's curvature-centre "
                  "circle (a contact angle beyond 90 degrees): the ring has been pushed past the "
                  "balls (a load or clearance the groove cannot hold)",
                  time_, static_cast<int>(sum[ROFF]));
    error->fix_error(FLERR, this, msg);
  }
  if (edge > shoulder / ohmdem::kDegree) {
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "keyword 'shoulder': at t = %g s a contact ellipse reaches %g deg across the "
                  "groove (contact angle plus its half-width), past the shoulder at %g deg: the "
                  "load is more than the groove holds",
                  time_, edge, shoulder / ohmdem::kDegree);
    error->fix_error(FLERR, this, msg);
  }
  check_runaway();
}

void FixBearingRace::initial_integrate_3d()
{
  const double dt = update->dt;
  evaluate_variables();
  ring_half_kick_3d(dt);
  angle_ += dt * target_omega(time_ + 0.5 * dt);
  u_ += dt * u_dot_;
  cx_ += dt * vcx_;
  cy_ += dt * vcy_;
  cz_ += dt * vcz_;
  tilt_[0] += dt * tilt_rate_[0];
  tilt_[1] += dt * tilt_rate_[1];
  time_ += dt;
  if (settings_.load == Load::Settle && !frozen_ && time_ >= settings_.settle_time) {
    frozen_ = true;
    u_dot_ = 0.0;
  }
}

// The housing's spring on the outer ring's centre (N): back toward the axis it was mounted on.
void FixBearingRace::housing_force(double &hx, double &hy) const
{
  hx = -settings_.model3d.housing * (cx_ - axis_x_);
  hy = -settings_.model3d.housing * (cy_ - axis_y_);
}

// Half a velocity-Verlet kick: the radius (load force, settle) as in model 2d; the outer ring on
// its housing: its centre in the plane under the housing's spring; the ring free in space (load
// radial): its centre under F d + Fa z (z held with preload) and its tilt under M about z x d;
// each against the balls' reactions and the viscous damping.
void FixBearingRace::ring_half_kick_3d(double dt)
{
  const double h = 0.5 * dt;
  const Load load = settings_.load;
  const double mass = settings_.ring_mass, damp = settings_.ring_damp;
  const ohmdem::RaceSettings::Model3d &m3 = settings_.model3d;
  if ((load == Load::Force || load == Load::Settle) && !frozen_) {
    u_dot_ += h * (load_force_ - radial_sum_ - damp * u_dot_) / mass;
  } else if (settings_.on_housing()) {
    double hx = 0.0, hy = 0.0;
    housing_force(hx, hy);
    vcx_ += h * (hx - fx_ - damp * vcx_) / mass;
    vcy_ += h * (hy - fy_ - damp * vcy_) / mass;
  } else if (load == Load::Radial) {
    vcx_ += h * (load_fx_ - fx_ - damp * vcx_) / mass;
    vcy_ += h * (load_fy_ - fy_ - damp * vcy_) / mass;
    if (!m3.preload_set) vcz_ += h * (m3.axial - fz_ - damp * vcz_) / mass;
    const double mx = -settings_.dir_uy * m3.moment, my = settings_.dir_ux * m3.moment;
    tilt_rate_[0] += h * (mx + moment_[0] - tilt_damp_ * tilt_rate_[0]) / tilt_inertia_;
    tilt_rate_[1] += h * (my + moment_[1] - tilt_damp_ * tilt_rate_[1]) / tilt_inertia_;
  }
}

double FixBearingRace::compute_vector_3d(int n)
{
  const double ux = settings_.dir_ux, uy = settings_.dir_uy;
  switch (n) {  // after the planar values (doc/fix_bearing_race.md: 16 to 23)
    case 0:
      return alpha_mean_;
    case 1:
      return alpha_max_;
    case 2:  // relative to the other ring: it moves on a housing
      return (cx_ - (other_race_ ? other_race_->cx_ : axis_x_)) * ux +
             (cy_ - (other_race_ ? other_race_->cy_ : axis_y_)) * uy;
    case 3:
      return cz_ - (other_race_ ? other_race_->cz_ : 0.0);
    case 4:
      return -tilt_[0] * uy + tilt_[1] * ux;  // about z x d
    case 5:
      return tilt_[0] * ux + tilt_[1] * uy;  // about d
    case 6:
      return -fz_;  // the balls push the ring with the opposite of its force on them
    case 7:
      return -moment_[0] * uy + moment_[1] * ux;
    default:
      return 0.0;
  }
}

ohmdem::ContactEllipse FixBearingRace::ellipse_of(int i, ohmdem::AreaModel model) const
{
  const double *row = array_atom[i];
  if (three_d()) return model3d_->hertz.ellipse(row[COSA], row[FN], model);
  return model_->hertz.ellipse(row[FN]);
}

FixBearingRace::FilmGeometry FixBearingRace::film_geometry_3d(int i, ohmdem::AreaModel model) const
{
  FilmGeometry f;
  const double *row = array_atom[i];
  const ohmdem::RingMotion3d ring = ring_motion_3d();
  ohmdem::TorusGroove g = model3d_->groove;
  g.centre_radius += settings_.inner ? u_ : -u_;
  const Vec3 rel{atom->x[i][0] - cx_, atom->x[i][1] - cy_, atom->x[i][2] - cz_};
  const auto geo = ohmdem::torus_geometry(g, ring.tilted ? ring.tilt.apply_transpose(rel) : rel);
  const double cos_alpha = std::min(1.0, std::max(0.0, geo.cos_alpha));
  const ohmdem::CurvatureSums s = ohmdem::torus_curvatures(g, cos_alpha);
  f.rx = 1.0 / s.A;
  f.ry = 1.0 / s.B;
  f.e_prime = 2.0 * model3d_->hertz.E_eff();
  f.fn = row[FN];
  f.pressed = row[FN] > 0.0;
  if (f.pressed) {
    const ohmdem::ContactEllipse e = model3d_->hertz.ellipse(row[COSA], row[FN], model);
    f.a = e.a;
    f.b = e.b;
    f.speed = row[ROLL];
  } else {
    f.gap = -geo.delta;
  }
  return f;
}

double FixBearingRace::contact_angle_3d(int i, const ohmdem::RingMotion3d &ring) const
{
  const Vec3 rel{atom->x[i][0] - cx_, atom->x[i][1] - cy_, atom->x[i][2] - cz_};
  ohmdem::TorusGroove g = model3d_->groove;
  g.centre_radius += settings_.inner ? u_ : -u_;
  const auto geo = ohmdem::torus_geometry(g, ring.tilted ? ring.tilt.apply_transpose(rel) : rel);
  return std::atan2(geo.sin_alpha, geo.cos_alpha);
}

double FixBearingRace::defect_recess_3d(int i, double alpha, bool &in_zone) const
{
  const double dx = atom->x[i][0] - cx_, dy = atom->x[i][1] - cy_;
  double recess = 0.0;
  for (const auto *d : defects_)
    recess += d->recess_at(defect_surface_, atom->tag[i], dx, dy, alpha, in_zone);
  return recess;
}

bool FixBearingRace::reapply_restored_forces_3d()
{
  if (!restored_) return false;
  restored_ = false;
  array_atom = state_->array_atom;
  double **f = atom->f, **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; ++k) {
      f[i][k] += array_atom[i][FX + k];
      torque[i][k] += array_atom[i][TX + k];
    }
  }
  return true;
}

