// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant; see lubricated_bearing.h.
#include "ELECTRIC/lubricated_bearing.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "common/constants.h"
#include "lubrication/contact_admittance.h"

using namespace LAMMPS_NS;
namespace lub = ohmdem::lubrication;

namespace {

// The mean entrainment speed of a ball-race contact at point p: the tangential component of
// the mean of the two surfaces' velocities, relative to the contact point, which travels with
// the ball's orbit about the ring centre c. Pure rolling on a fixed outer ring gives
// (omega_i - omega_cage) R_i at the inner contact.
double entrainment_speed(const double *x, const double *v, double omega_z, double px, double py,
                         const FixBearingRace &race)
{
  double cx, cy, rvx, rvy;
  race.centre(cx, cy);
  race.surface_velocity(px, py, rvx, rvy);
  const double bvx = v[0] - omega_z * (py - x[1]), bvy = v[1] + omega_z * (px - x[0]);
  const double ox = x[0] - cx, oy = x[1] - cy;
  const double orbit = (ox * v[1] - oy * v[0]) / (ox * ox + oy * oy);
  const double pvx = -orbit * (py - cy), pvy = orbit * (px - cx);
  double nx = px - x[0], ny = py - x[1];
  const double n = std::sqrt(nx * nx + ny * ny);
  nx /= n;
  ny /= n;
  const double ux = 0.5 * (bvx + rvx) - pvx, uy = 0.5 * (bvy + rvy) - pvy;
  return std::fabs(-ny * ux + nx * uy);
}

// The gap between a ball and a race it does not press (m), along the line through the ring
// centre.
double race_gap(const double *x, double r, const FixBearingRace &race)
{
  double cx, cy;
  race.centre(cx, cy);
  const double d = std::hypot(x[0] - cx, x[1] - cy);
  return race.is_inner() ? d - r - race.current_radius() : race.current_radius() - d - r;
}

}  // namespace

LubricatedBearing::LubricatedBearing(LAMMPS *lmp, const LubricationSettings &settings)
    : Pointers(lmp), settings_(settings)
{
  path_ = lub::lubricant_path(settings.lubricant, lub::default_lubricant_dir());
  const std::string name = path_.substr(path_.rfind('/') + 1);
  state_ = lub::state_at(lub::read_lubricant_file(path_, name), settings.temperature);
}

void LubricatedBearing::init(const ResistanceContext &)
{
  geometry_ready_ = false;
}

// At the first evaluation of a run: the races' contact geometry exists once they are set up.
void LubricatedBearing::set_geometry(const ResistanceContext &context)
{
  geometry_ready_ = true;
  ContactSet &contacts = *context.contacts;
  const auto &races = contacts.races();
  const int high = context.high.index, low = context.low.index;
  dry_ = ohmdem::BallBetweenRaces(context.model, contacts.race_geometry(high),
                                  contacts.race_geometry(low),
                                  context.gamma_type[races[high]->race_type()],
                                  context.gamma_type[races[low]->race_type()], context.gamma_type);
}

LubricatedResult LubricatedBearing::evaluate(const ResistanceContext &context)
{
  if (!geometry_ready_) set_geometry(context);
  ContactSet &contacts = *context.contacts;
  const auto &races = contacts.races();
  const int side_race[2] = {context.high.index, context.low.index};
  const double omega_exc = 2.0 * ohmdem::kPi * settings_.fexc;
  const double inf = std::numeric_limits<double>::infinity();
  double hmin[2] = {inf, inf}, lambda_min = inf;  // [0] inner, [1] outer

  balls_.clear();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context.groupbit)) continue;
    const double *x = atom->x[i], *v = atom->v[i];
    const double r = atom->radius[i], gamma = context.gamma_type[atom->type[i]];
    ohmdem::RaceContactView view[2] = {races[side_race[0]]->contact_of(i),
                                       races[side_race[1]]->contact_of(i)};
    // The ball's dry (metallic) conductance, shared equally by its two contacts.
    double g_ball = 0.0;
    if (gamma > 0.0 && (view[0].fn() > 0.0 || view[1].fn() > 0.0)) {
      const double f0 = view[0].fn() > 0.0 ? view[0].fn() : view[1].fn();
      const double f1 = view[1].fn() > 0.0 ? view[1].fn() : view[0].fn();
      const ohmdem::RaceContactView &a = view[0].fn() > 0.0 ? view[0] : view[1];
      const ohmdem::RaceContactView &b = view[1].fn() > 0.0 ? view[1] : view[0];
      double u[3] = {a.point_x() - x[0], a.point_y() - x[1], 0.0};
      double w[3] = {b.point_x() - x[0], b.point_y() - x[1], 0.0};
      if (&a == &b) w[0] = -u[0], w[1] = -u[1];  // one race: a ball facing the other
      g_ball = dry_.conductance(atom->type[i], gamma, r, f0, f1, u, w);
    }
    std::complex<double> y[2];
    lub::ContactAdmittance c[2];  // the loaded contacts (the film can break down)
    for (int s = 0; s < 2; ++s) {
      const FixBearingRace &race = *races[side_race[s]];
      const ohmdem::HertzContact &hertz = contacts.race_geometry(side_race[s]);
      const ohmdem::CurvatureSums sums = hertz.sums();
      const double rx = 1.0 / sums.A, ry = 1.0 / sums.B;
      if (!(view[s].fn() > 0.0)) {
        // Over a pit the ball lifted off the pit's surface: no closer than the nominal surface.
        const double gap = std::max(race_gap(x, r, race), 0.0) + race.recess_of(i);
        y[s] = {0.0, omega_exc * lub::idle_gap_capacitance(gap, rx, ry, settings_.wetted,
                                                           state_.eps_r, settings_.roughness)};
        continue;
      }
      const ohmdem::ContactEllipse e = hertz.ellipse(view[s].fn());
      lub::ContactInput in;
      in.film.load = view[s].fn();
      in.film.speed =
          entrainment_speed(x, v, atom->omega[i][2], view[s].point_x(), view[s].point_y(), race);
      in.film.rx = rx;
      in.film.ry = ry;
      in.film.e_prime = 2.0 * hertz.E_eff();
      in.film.eta = state_.eta;
      in.film.alpha = state_.alpha;
      in.film.k = e.a / e.b;
      in.a = e.a;
      in.b = e.b;
      in.sigma = settings_.roughness;
      in.r_wet = settings_.wetted;
      in.eps_r = state_.eps_r;
      in.resistivity = state_.resistivity;
      in.g_dry = view[s].conducts() ? 2.0 * g_ball : 0.0;  // a defect zone: no metal
      in.recess = race.recess_of(i);                       // over a pit the gap grows
      c[s] = lub::contact_admittance(in);
      y[s] = c[s].y(omega_exc);
      const int k = race.is_inner() ? 0 : 1;
      hmin[k] = std::min(hmin[k], c[s].film.minimum);
      lambda_min = std::min(lambda_min, c[s].lambda);
    }
    if (settings_.breakdown > 0.0) {  // the film of a contact under too high a voltage
      const bool loaded[2] = {view[0].fn() > 0.0, view[1].fn() > 0.0};
      lub::break_down_ball(y, c, loaded, settings_.excitation, settings_.breakdown, omega_exc);
    }
    const std::complex<double> ball = lub::series(y[0], y[1]);
    balls_.push_back({static_cast<std::int64_t>(atom->tag[i]), {ball.real(), ball.imag()}});
  }
  // Admittances added in tag order: the same Z with any number of processes.
  const auto sum = ohmdem::ordered_sum<2>(gather_.gather(balls_, world));
  double mins[3] = {hmin[0], hmin[1], lambda_min}, all[3];
  MPI_Allreduce(mins, all, 3, MPI_DOUBLE, MPI_MIN, world);
  const lub::Impedance z = lub::impedance({sum[0], sum[1]}, omega_exc);
  LubricatedResult out;
  out.z_abs = z.z_abs;
  out.z_phase = z.z_phase;
  out.c_parallel = z.c_parallel;
  out.r_parallel = z.r_parallel;
  out.hmin_inner = all[0];
  out.hmin_outer = all[1];
  out.lambda_min = all[2];
  return out;
}
