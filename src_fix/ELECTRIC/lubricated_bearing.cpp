// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant; see lubricated_bearing.h.
#include "ELECTRIC/lubricated_bearing.h"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <exception>
#include <limits>
#include <string>
#include <type_traits>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/lubricated_network.h"
#include "atom.h"
#include "common/constants.h"
#include "error.h"
#include "lubrication/bearing_kernels.h"
#include "lubrication/contact_admittance.h"
#include "lubrication/pit_contact.h"
#include "lubrication/race_admittance.h"

using namespace LAMMPS_NS;
namespace lub = ohmdem::lubrication;

namespace {

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
    : Pointers(lmp),
      settings_(settings),
      omega_(2.0 * ohmdem::kPi * settings.fexc),
      network_(std::make_unique<LubricatedNetwork>())
{
  path_ = lub::lubricant_path(settings.lubricant, lub::default_lubricant_dir());
  const std::string name = path_.substr(path_.rfind('/') + 1);
  state_ = lub::state_at(lub::read_lubricant_file(path_, name), settings.temperature);
  if (settings_.breakdown_file && !(state_.breakdown > 0.0))
    throw lub::LubricantError("breakdown lubricant: the file '" + path_ +
                              "' gives no breakdown field (give one in V/m)");
  if (settings_.breakdown_file) settings_.breakdown = state_.breakdown;
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
  // What a race's contacts share (lib/lubrication/race_admittance.h): once per run.
  for (int side = 0; side < 2; ++side) {
    const int k = side == 0 ? high : low;
    race_[side] = races[k];
    const ohmdem::HertzContact &hertz = contacts.race_geometry(k);
    const ohmdem::CurvatureSums sums = hertz.sums();
    const ohmdem::ContactEllipse unit = hertz.ellipse(1.0);  // a = a(1 N) fn^(1/3)
    lub::RaceInput in;
    in.rx = 1.0 / sums.A;
    in.ry = 1.0 / sums.B;
    in.e_prime = 2.0 * hertz.E_eff();
    in.a_coef = unit.a;
    in.b_coef = unit.b;
    set_oil(in, settings_, state_);
    film_[side] = lub::RaceAdmittance(in);
    inner_[side] = races[k]->is_inner() ? 0 : 1;
  }
}

LubricatedBearing::~LubricatedBearing() = default;

// The ball's dry (metallic) conductance between its two races, 0 when it touches none.
double LubricatedBearing::ball_dry_conductance(const ResistanceContext &context, int i)
{
  const auto &races = context.contacts->races();
  const double *x = atom->x[i];
  const double r = atom->radius[i], gamma = context.gamma_type[atom->type[i]];
  const ohmdem::RaceContactView v0 = races[context.high.index]->contact_of(i);
  const ohmdem::RaceContactView v1 = races[context.low.index]->contact_of(i);
  if (!(gamma > 0.0) || !(v0.fn() > 0.0 || v1.fn() > 0.0)) return 0.0;
  const double f0 = v0.fn() > 0.0 ? v0.fn() : v1.fn();
  const double f1 = v1.fn() > 0.0 ? v1.fn() : v0.fn();
  const ohmdem::RaceContactView &a = v0.fn() > 0.0 ? v0 : v1;
  const ohmdem::RaceContactView &b = v1.fn() > 0.0 ? v1 : v0;
  double u[3] = {a.point_x() - x[0], a.point_y() - x[1], 0.0};
  double w[3] = {b.point_x() - x[0], b.point_y() - x[1], 0.0};
  if (&a == &b) w[0] = -u[0], w[1] = -u[1];  // one race: a ball facing the other
  return dry_.conductance(atom->type[i], gamma, r, f0, f1, u, w);
}

// A pressed contact's inputs go to its race's batch (its metallic part is half the ball's dry
// path: 2 g_ball, the two in series give g_ball); a race the ball does not press gets the
// capacitance of the gap to it, as a record of its own. Returns the contact's index in its
// race's batch, or -1 - its index in idle_. Inlined into evaluate()'s loop, its only caller.
__attribute__((always_inline)) inline int LubricatedBearing::collect(
    int i, int side, double g_ball, const ohmdem::RaceContactView &view, double speed)
{
  const FixBearingRace &race = *race_[side];
  // A race pit within the wetted circle is a strip across the raceway (pit_strip); other
  // defects under the contact (a ball's pit) add their recess over the whole circle.
  ohmdem::PitView &pit = pit_;  // set, and read, only near a pit
  double recess = 0.0;  // kept in a register: pit_near writes through a pointer, when called
  bool near_pit = false;
  if (race.has_defects()) {
    double rest;
    near_pit = race.pit_near(i, settings_.wetted, pit, rest);
    recess = rest;
  }
  if (!(view.fn() > 0.0)) {
    LubricatedContact &out = idle_.emplace_back();
    out.tag = static_cast<std::int64_t>(atom->tag[i]);
    out.side = side;
    // Over a pit the ball lifted off the pit's surface: no closer than the nominal surface.
    const double gap = std::max(race_gap(atom->x[i], atom->radius[i], race), 0.0) + recess;
    out.c = near_pit ? lub::idle_over_pit(film_[side].input(), gap, pit_strip(pit))
                     : film_[side].idle(gap);
    out.y = {0.0, omega() * out.c};
    // The gap at the contact point (with the strip's recess there).
    out.h_central = out.h_min = near_pit ? gap + lub::strip_recess(pit_strip(pit), 0.0) : gap;
    out.lambda = out.h_min / settings_.roughness;
    return -static_cast<int>(idle_.size());
  }
  // Into the race's batch; the few contacts near a race pit also get the Hertz zone and the gap
  // over the strip, once the batch has the contact's film (evaluate()).
  const std::size_t index =
      batch_[side].add_reserved(view.fn(), speed,
                                view.conducts() ? 2.0 * g_ball : 0.0,  // a defect zone: no metal
                                recess);  // other defects' recess under the contact
  if (near_pit) pit_fixes_.push_back({side, index, view.fn(), recess, pit});
  return static_cast<int>(index);
}

// The records of the last evaluation, two per ball, from the races' admittances and the idle
// contacts' records: built when read (contacts()), or by evaluate() when it needs them.
void LubricatedBearing::build_records() const
{
  contacts_.resize(2 * balls_in_.size());
  for (std::size_t n = 0; n < balls_in_.size(); ++n)
    for (int side = 0; side < 2; ++side) {
      const int ref = balls_in_[n].ref[side];
      LubricatedContact &c = contacts_[2 * n + side];
      if (ref < 0) {
        c = idle_[-1 - ref];
        continue;
      }
      c = LubricatedContact();
      c.tag = balls_in_[n].tag;
      c.side = side;
      c.loaded = true;
      fill(films_[side][ref], c);
    }
  records_ready_ = true;
}

const std::vector<LubricatedContact> &LubricatedBearing::contacts() const
{
  if (!records_ready_) build_records();
  return contacts_;
}

void LubricatedBearing::fill(const lub::ContactAdmittance &c, LubricatedContact &out) const
{
  out.y = c.y(omega());
  out.h_central = c.film.central;
  out.h_min = c.film.minimum;
  out.lambda = c.lambda;
  out.c = c.capacitance();
  out.g = c.g;
}

void LubricatedBearing::break_down(LubricatedContact pair[2],
                                   const lub::ContactAdmittance film[2]) const
{
  std::complex<double> y[2] = {pair[0].y, pair[1].y};
  const bool loaded[2] = {pair[0].loaded, pair[1].loaded};
  if (lub::break_down_ball(y, film, loaded, settings_.excitation, settings_.breakdown, omega()) ==
      0)
    return;
  for (int s = 0; s < 2; ++s) {
    if (y[s] == pair[s].y) continue;
    const lub::ContactAdmittance broken = lub::broken_down(film[s]);
    pair[s].y = y[s];
    pair[s].c = broken.capacitance();
    pair[s].g = broken.g;
  }
}

void LubricatedBearing::evaluate(const ResistanceContext &context, bool gather,
                                 const double *g_dry)
{
  if (!geometry_ready_) set_geometry(context);
  if (race_[0]->three_d())
    evaluate_3d(context, gather, g_dry);
  else if (settings_.kernel == lub::BearingKernel::plain)
    evaluate_with<lub::PlainKernel>(context, gather, g_dry);
  else
    evaluate_with<lub::LanesKernel>(context, gather, g_dry);
}

template <class Kernel>
void LubricatedBearing::evaluate_with(const ResistanceContext &context, bool gather,
                                      const double *g_dry)
{
  const double inf = std::numeric_limits<double>::infinity();
  double hmin[2] = {inf, inf}, lambda_min = inf;  // [0] inner, [1] outer

  // Sized once for this process's atoms (the same from step to step: no work), written by
  // index and cut to the balls at the end: no capacity test per ball.
  balls_in_.resize(atom->nlocal);
  std::size_t nballs = 0;
  idle_.clear();
  pit_fixes_.clear();
  records_ready_ = false;
  for (int side = 0; side < 2; ++side) {
    lub::RaceFrame &m = motion_[side];
    race_[side]->centre(m.cx, m.cy);
    race_[side]->rigid_motion(m.w, m.vcx, m.vcy);
    batch_[side].clear();
    batch_[side].reserve(atom->nlocal);  // one contact per ball at most (collect())
  }
  // Per ball its two contacts: per race its pressed contacts' inputs, or an idle record ...
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context.groupbit)) continue;
    // The closed form's conductance of this step where it has one (NaN: it has none).
    const double g_ball =
        g_dry && !std::isnan(g_dry[i]) ? g_dry[i] : ball_dry_conductance(context, i);
    const ohmdem::RaceContactView view[2] = {race_[0]->contact_of(i), race_[1]->contact_of(i)};
    // Both sides' speeds (a race the ball does not press: computed, not used).
    const lub::BallMotion ball = {atom->x[i],
                                  atom->v[i],
                                  atom->omega[i][2],
                                  {view[0].point_x(), view[1].point_x()},
                                  {view[0].point_y(), view[1].point_y()}};
    const std::array<double, 2> speed = Kernel::speeds(ball, motion_);
    const int ref0 = collect(i, 0, g_ball, view[0], speed[0]);
    const int ref1 = collect(i, 1, g_ball, view[1], speed[1]);
    balls_in_[nballs++] = {static_cast<std::int64_t>(atom->tag[i]), {ref0, ref1}};
  }
  balls_in_.resize(nballs);
  // ... their admittances, a race's contacts together (lib/lubrication, race_admittance.h) ...
  for (int side = 0; side < 2; ++side) films_[side].resize(batch_[side].size());
  // (with each race's smallest films: a race pit's correction below leaves them as they are)
  const lub::RaceMinima minima = Kernel::contacts(film_[0], batch_[0], films_[0].data(), film_[1],
                                                  batch_[1], films_[1].data());
  for (int side = 0; side < 2; ++side) {
    const int k = inner_[side];
    hmin[k] = std::min(hmin[k], minima[side].minimum);
    lambda_min = std::min(lambda_min, minima[side].lambda);
  }
  for (const PitFix &f : pit_fixes_)
    lub::contact_over_pit(film_[f.side].input(), f.fn, f.rest, pit_strip(f.pit),
                          films_[f.side][f.index]);
  combine<Kernel>(context, gather, hmin, lambda_min);
}

// The balls of this evaluation (balls_in_, films_, idle_): each its two contacts in series,
// broken down where the excitation breaks a film, and the bearing's admittance, from the
// general network or the balls in parallel in tag order.
template <class Kernel>
void LubricatedBearing::combine(const ResistanceContext &context, bool gather, const double hmin[2],
                                double lambda_min)
{
  const std::size_t nballs = balls_in_.size();
  // The records only where this step needs them (breakdown changes them; the network and an
  // export read them); else when read.
  const bool breakdown = settings_.breakdown > 0.0;
  if (breakdown || settings_.network || gather) build_records();
  balls_.resize(nballs);
  const lub::ContactAdmittance *const films[2] = {films_[0].data(), films_[1].data()};
  const BallRefs *const refs = balls_in_.data();
  ohmdem::TaggedValues<2> *const balls = balls_.data();
  const double omega = omega_;
  // (the breakdown test once: the loop's body twice, with and without it)
  const auto each_ball = [&](auto with_breakdown) {
    for (std::size_t n = 0; n < nballs; ++n) {
      const BallRefs &b = refs[n];
      std::complex<double> y[2];  // f.y(omega): G + j omega C
      const lub::ContactAdmittance *film[2] = {nullptr, nullptr};
      for (int side = 0; side < 2; ++side) {
        const int ref = b.ref[side];
        if (ref < 0) {
          y[side] = idle_[-1 - ref].y;
          continue;
        }
        const lub::ContactAdmittance &f = films[side][ref];
        film[side] = &f;
        y[side] = {f.g, omega * f.capacitance()};
      }
      if constexpr (decltype(with_breakdown)::value) {
        // break_down_ball reads the films of the pressed contacts only.
        LubricatedContact *const pair = &contacts_[2 * n];
        lub::ContactAdmittance both[2];
        for (int side = 0; side < 2; ++side)
          if (film[side]) both[side] = *film[side];
        break_down(pair, both);
        for (int side = 0; side < 2; ++side) y[side] = pair[side].y;
      }
      const std::complex<double> ball = Kernel::series(y[0], y[1]);
      balls[n].tag = b.tag;
      balls[n].v = {ball.real(), ball.imag()};
    }
  };
  if (breakdown)
    each_ball(std::true_type());
  else
    each_ball(std::false_type());
  std::complex<double> y_bearing;
  if (settings_.network || gather) network_->gather(contacts_, world);
  if (settings_.network) {
    // Every process solves the same gathered system: the same Z bits everywhere.
    std::complex<double> z;
    try {
      z = network_->solve(context.current);
    } catch (const std::exception &e) {  // every process solves the same system: all throw
      error->all(
          FLERR,
          (std::string("compute network/resistance: the lubricated network: ") + e.what()).c_str());
    }
    y_bearing = std::isinf(z.real()) ? std::complex<double>(0.0, 0.0) : 1.0 / z;
  } else {
    // Admittances added in tag order: the same Z with any number of processes.
    const auto sum = ohmdem::ordered_sum<2>(gather_.gather(balls_, world));
    y_bearing = {sum[0], sum[1]};
  }
  local_min_[0] = hmin[0];
  local_min_[1] = hmin[1];
  local_min_[2] = lambda_min;
  y_bearing_ = y_bearing;
  current_ = context.current;
}

template void LubricatedBearing::combine<lub::PlainKernel>(const ResistanceContext &, bool,
                                                           const double[2], double);

void LubricatedBearing::impedance(LubricatedResult &out) const
{
  const lub::Impedance z = lub::impedance(y_bearing_, omega());
  out.z_abs = z.z_abs;
  out.z_phase = z.z_phase;
  out.c_parallel = z.c_parallel;
  out.r_parallel = z.r_parallel;
  out.v_high = y_bearing_ == std::complex<double>(0.0, 0.0) ? std::complex<double>(0.0, 0.0)
                                                            : current_ / y_bearing_;
}

void LubricatedBearing::minima(LubricatedResult &out) const
{
  double all[3];
  MPI_Allreduce(local_min_, all, 3, MPI_DOUBLE, MPI_MIN, world);
  out.hmin_inner = all[0];
  out.hmin_outer = all[1];
  out.lambda_min = all[2];
}
