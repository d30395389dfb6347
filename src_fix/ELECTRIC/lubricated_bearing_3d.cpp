// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant, on the races of model 3d (lubricated_bearing.h):
// each pressed contact is Hamrock and Dowson's film (lib/lubrication) with its own effective
// radii at its contact angle (Rx = 1/A, Ry = 1/B of contact/torus_race.h: for a ball on the
// pitch circle Hamrock's Rx = d (d_m -+ d cos a) / (2 d_m)), its Hertz ellipse there (in the
// compute's area model, as model 2d's films) and the
// entrainment speed of its surfaces past the moving contact point in the rolling direction
// (contact/race_contact_3d.h); a race the ball does not press gets the capacitance of its gap
// along the contact line. The balls' two contacts in series (broken down where the excitation
// breaks a film), the balls in parallel in tag order or the general network, as in model 2d.
// doc/methods/bearing_3d.md, "Lubricated contacts".
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/lubricated_bearing.h"
#include "ELECTRIC/lubricated_network.h"
#include "ELECTRIC/resistance_path_closed_form.h"
#include "atom.h"
#include "lubrication/contact_admittance.h"
#include "lubrication/pit_contact.h"

using namespace LAMMPS_NS;
namespace lub = ohmdem::lubrication;

// Both spots pressed: the closed form's own conductance (ball_between_3d, so the network and
// the closed form agree to the bit); one pressed: the ball facing that race on both sides, as
// model 2d's ball_dry_conductance; neither: 0.
double LubricatedBearing::ball_dry_conductance_3d(const ResistanceContext &context, int i) const
{
  const bool pressed[2] = {race_[0]->contact_of(i).fn() > 0.0, race_[1]->contact_of(i).fn() > 0.0};
  if (!(context.gamma_type[atom->type[i]] > 0.0) || !(pressed[0] || pressed[1])) return 0.0;
  const FixBearingRace &a = *race_[pressed[0] ? 0 : 1], &b = *race_[pressed[1] ? 1 : 0];
  return 1.0 / ball_between_3d(context, a, b, *atom, i).total();
}

namespace {

// The race constants contact_over_pit and idle_over_pit read, for one contact of model 3d (its
// own radii and ellipse at its contact angle).
lub::RaceInput race_input_3d(const FixBearingRace::FilmGeometry &fg,
                             const LubricationSettings &settings, const lub::LubricantState &oil)
{
  lub::RaceInput r;
  r.rx = fg.rx;
  r.ry = fg.ry;
  r.e_prime = fg.e_prime;
  const double cbrt_fn = fg.pressed ? std::cbrt(fg.fn) : 0.0;
  r.a_coef = cbrt_fn > 0.0 ? fg.a / cbrt_fn : 0.0;
  r.b_coef = cbrt_fn > 0.0 ? fg.b / cbrt_fn : 0.0;
  set_oil(r, settings, oil);
  return r;
}

}  // namespace

void LubricatedBearing::evaluate_3d(const ResistanceContext &context, bool gather,
                                    const double *g_dry)
{
  const double inf = std::numeric_limits<double>::infinity();
  double hmin[2] = {inf, inf}, lambda_min = inf;  // [0] inner, [1] outer
  balls_in_.resize(atom->nlocal);
  std::size_t nballs = 0;
  idle_.clear();
  records_ready_ = false;
  for (auto &f : films_) f.clear();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context.groupbit)) continue;
    // The closed form's conductance of this step where it has one.
    const double g_ball =
        g_dry && !std::isnan(g_dry[i]) ? g_dry[i] : ball_dry_conductance_3d(context, i);
    int ref[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      const FixBearingRace &race = *race_[side];
      const FixBearingRace::FilmGeometry fg =
          race.film_geometry_3d(i, context.contacts->area_model());
      // A race pit within the wetted circle is a strip across the raceway, as in model 2d
      // (beside a narrow pit the film does not meet it); the other defects' recess (a ball's
      // pit) under the contact over the whole circle.
      double rest = 0.0;
      const bool near_pit = race.has_defects() && race.pit_near(i, settings_.wetted, pit_, rest);
      const lub::RaceInput frame =
          near_pit ? race_input_3d(fg, settings_, state_) : lub::RaceInput();
      if (!fg.pressed) {
        LubricatedContact &out = idle_.emplace_back();
        out.tag = static_cast<std::int64_t>(atom->tag[i]);
        out.side = side;
        // Over a pit the ball lifted off the pit's surface: no closer than the nominal surface.
        const double gap = std::max(fg.gap, 0.0) + rest;
        out.c = near_pit ? lub::idle_over_pit(frame, gap, pit_strip(pit_))
                         : lub::idle_gap_capacitance(gap, fg.rx, fg.ry, settings_.wetted,
                                                     state_.eps_r, settings_.roughness);
        out.y = {0.0, omega() * out.c};
        out.h_central = out.h_min = near_pit ? gap + lub::strip_recess(pit_strip(pit_), 0.0) : gap;
        out.lambda = out.h_min / settings_.roughness;
        ref[side] = -static_cast<int>(idle_.size());
        continue;
      }
      lub::ContactInput in;
      in.film.load = fg.fn;
      in.film.speed = fg.speed;
      in.film.rx = fg.rx;
      in.film.ry = fg.ry;
      in.film.e_prime = fg.e_prime;
      in.film.eta = state_.eta;
      in.film.alpha = state_.alpha;
      in.film.k = fg.a / fg.b;
      in.a = fg.a;
      in.b = fg.b;
      in.sigma = settings_.roughness;
      in.r_wet = settings_.wetted;
      in.eps_r = state_.eps_r;
      in.resistivity = state_.resistivity;
      in.g_dry = race.contact_of(i).conducts() ? 2.0 * g_ball : 0.0;  // a defect zone: no metal
      in.recess = rest;
      lub::ContactAdmittance c = lub::contact_admittance(in);
      if (near_pit) lub::contact_over_pit(frame, fg.fn, rest, pit_strip(pit_), c);
      const int k = inner_[side];
      hmin[k] = std::min(hmin[k], c.film.minimum);
      lambda_min = std::min(lambda_min, c.lambda);
      films_[side].push_back(c);
      ref[side] = static_cast<int>(films_[side].size()) - 1;
    }
    balls_in_[nballs++] = {static_cast<std::int64_t>(atom->tag[i]), {ref[0], ref[1]}};
  }
  balls_in_.resize(nballs);
  combine<lub::PlainKernel>(context, gather, hmin, lambda_min);
}
