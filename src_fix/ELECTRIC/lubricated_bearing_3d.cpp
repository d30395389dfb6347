// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant, on the races of model 3d (lubricated_bearing.h):
// each pressed contact is Hamrock and Dowson's film (lib/lubrication) with its own effective
// radii at its contact angle (Rx = 1/A, Ry = 1/B of contact/torus_race.h: for a ball on the
// pitch circle Hamrock's Rx = d (d_m -+ d cos a) / (2 d_m)), its Hertz ellipse there (in the
// compute's area model, as model 2d's films) and the
// entrainment speed of its surfaces past the moving contact point in the rolling direction
// (contact/race_contact_3d.h); a race the ball does not press gets the capacitance of its gap
// along the contact line. The balls' two contacts in series, the balls in parallel in tag order,
// as in model 2d. doc/methods/bearing_3d.md, "Lubricated contacts".
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
#include "atom.h"
#include "lubrication/contact_admittance.h"

using namespace LAMMPS_NS;
namespace lub = ohmdem::lubrication;

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
    // The closed form's conductance of this step (model 3d: always the closed form); none: 0.
    const double g_ball = g_dry && !std::isnan(g_dry[i]) ? g_dry[i] : 0.0;
    int ref[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      const FixBearingRace &race = *race_[side];
      const FixBearingRace::FilmGeometry fg =
          race.film_geometry_3d(i, context.contacts->area_model());
      if (!fg.pressed) {
        LubricatedContact &out = idle_.emplace_back();
        out.tag = static_cast<std::int64_t>(atom->tag[i]);
        out.side = side;
        const double gap = std::max(fg.gap, 0.0);
        out.c = lub::idle_gap_capacitance(gap, fg.rx, fg.ry, settings_.wetted, state_.eps_r,
                                          settings_.roughness);
        out.y = {0.0, omega() * out.c};
        out.h_central = out.h_min = gap;
        out.lambda = gap / settings_.roughness;
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
      in.g_dry = race.contact_of(i).conducts() ? 2.0 * g_ball : 0.0;
      const lub::ContactAdmittance c = lub::contact_admittance(in);
      const int k = inner_[side];
      hmin[k] = std::min(hmin[k], c.film.minimum);
      lambda_min = std::min(lambda_min, c.lambda);
      films_[side].push_back(c);
      ref[side] = static_cast<int>(films_[side].size()) - 1;
    }
    balls_in_[nballs++] = {static_cast<std::int64_t>(atom->tag[i]), {ref[0], ref[1]}};
  }
  balls_in_.resize(nballs);
  if (gather) build_records();
  balls_.resize(nballs);
  for (std::size_t n = 0; n < nballs; ++n) {
    std::complex<double> y[2];
    for (int side = 0; side < 2; ++side) {
      const int r = balls_in_[n].ref[side];
      y[side] = r < 0 ? idle_[-1 - r].y : films_[side][r].y(omega());
    }
    const std::complex<double> s = y[0] + y[1];
    const std::complex<double> ball = s == 0.0 ? 0.0 : y[0] * y[1] / s;
    balls_[n].tag = balls_in_[n].tag;
    balls_[n].v = {ball.real(), ball.imag()};
  }
  if (gather) network_->gather(contacts_, world);
  const auto sum = ohmdem::ordered_sum<2>(gather_.gather(balls_, world));
  local_min_[0] = hmin[0];
  local_min_[1] = hmin[1];
  local_min_[2] = lambda_min;
  y_bearing_ = {sum[0], sum[1]};
  current_ = context.current;
}
