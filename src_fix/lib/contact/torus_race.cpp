// SPDX-License-Identifier: GPL-2.0-or-later
// The 3D raceway's exact Hertz table; see torus_race.h and doc/methods/bearing_3d.md.
#include "contact/torus_race.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"
#include "common/fast_cbrt.h"

namespace ohmdem {

CurvatureSums torus_curvatures(const TorusGroove &g, double cos_alpha)
{
  const bool inner = g.side == RaceSide::Inner;
  const double rho_s = g.centre_radius + (inner ? -1.0 : 1.0) * g.groove_radius * cos_alpha;
  const double rolling = (inner ? 1.0 : -1.0) * cos_alpha / rho_s;
  return {1.0 / g.ball_radius + rolling, 1.0 / g.ball_radius - 1.0 / g.groove_radius};
}

double torsion_shear_modulus(double E1, double nu1, double E2, double nu2)
{
  return 1.0 / (2.0 * (1.0 + nu1) / E1 + 2.0 * (1.0 + nu2) / E2);
}

AngularHertz::AngularHertz(const TorusGroove &groove, double E_eff, double G_eff, double G_torsion,
                           int intervals)
    : groove_(groove), E_eff_(E_eff), G_eff_(G_eff), G_torsion_(G_torsion), intervals_(intervals)
{
  const TorusGroove &g = groove;
  if (!(g.ball_radius > 0.0)) throw std::invalid_argument("ball radius must be positive");
  if (!(g.groove_radius > g.ball_radius))
    throw std::invalid_argument("groove radius must be larger than the ball radius");
  // The race surface must stay off the axis for every contact angle: rho_S > 0 at cos = 1.
  const double rho_min = g.side == RaceSide::Inner ? g.centre_radius - g.groove_radius
                                                   : g.centre_radius + g.groove_radius;
  if (!(rho_min > g.ball_radius))
    throw std::invalid_argument("the groove bottom radius (" + std::to_string(rho_min) +
                                " m) must be larger than the ball radius");
  if (!(G_eff > 0.0) || !(G_torsion > 0.0))
    throw std::invalid_argument("shear modulus must be positive");
  if (intervals < 4) throw std::invalid_argument("the Hertz table needs at least 4 intervals");
  table_.reserve(intervals_ + 1);
  mechanics_.reserve(intervals_ + 1);
  for (int k = 0; k <= intervals_; ++k) {
    const HertzAtAngle h = exact(static_cast<double>(k) / intervals_);
    table_.push_back(h);
    const double k3 = std::cbrt(h.K);  // Q^(1/3) = K^(1/3) sqrt(delta)
    mechanics_.push_back({h.K, h.kt_coef, 2.0 * h.b1 * k3, h.spin_coef * h.K * k3, h.torsion_coef});
  }
}

HertzAtAngle AngularHertz::exact(double cos_alpha) const
{
  const CurvatureSums sums = torus_curvatures(groove_, cos_alpha);
  const HertzContact exact(sums, E_eff_, AreaModel::Exact);
  const HertzContact greenwood(sums, E_eff_, AreaModel::Greenwood);
  const ContactEllipse e = exact.ellipse(1.0), eg = greenwood.ellipse(1.0);
  HertzAtAngle h;
  h.K = exact.stiffness_constant();
  h.a1 = e.a;
  h.b1 = e.b;
  h.a1_greenwood = eg.a;
  h.b1_greenwood = eg.b;
  const double c1 = std::sqrt(e.a * e.b);
  h.kt_coef = 8.0 * G_eff_ * c1 * std::cbrt(h.K);
  // E(e) of the ellipse, e^2 = 1 - (b/a)^2: complete_elliptic takes the complementary modulus.
  const CompleteElliptic ce = complete_elliptic(e.b / e.a);
  h.spin_coef = 3.0 * e.a * ce.E / 8.0;
  h.torsion_coef = 16.0 / 3.0 * G_torsion_ * c1 * c1 * c1 * h.K;
  return h;
}

ContactEllipse AngularHertz::ellipse(double cos_alpha, double fn, AreaModel model) const
{
  ContactEllipse e;
  if (!(fn > 0.0)) return e;
  const HertzAtAngle h = at(cos_alpha);
  const double q = cbrt_fast(fn);
  e.a = (model == AreaModel::Exact ? h.a1 : h.a1_greenwood) * q;
  e.b = (model == AreaModel::Exact ? h.b1 : h.b1_greenwood) * q;
  e.c = std::sqrt(e.a * e.b);
  e.area = kPi * e.a * e.b;
  return e;
}

}  // namespace ohmdem
