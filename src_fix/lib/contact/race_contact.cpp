// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/race_contact.h"

#include <cmath>
#include <stdexcept>

namespace ohmdem {

static CurvatureSums race_curvatures(RaceSide side, double rb, double R, double Rg)
{
  if (!(rb > 0.0)) throw std::invalid_argument("ball radius must be positive");
  if (!(Rg > rb)) throw std::invalid_argument("groove radius must be larger than the ball radius");
  if (side == RaceSide::Outer && !(R > rb))
    throw std::invalid_argument("outer race radius must be larger than the ball radius");
  return side == RaceSide::Inner ? ball_inner_race(rb, R, Rg) : ball_outer_race(rb, R, Rg);
}

RaceContactModel::RaceContactModel(RaceSide side_, double ball_radius_, double race_radius,
                                   double groove_radius, double E_eff, double G_eff_,
                                   double restitution, double friction_)
    : side(side_),
      ball_radius(ball_radius_),
      hertz(race_curvatures(side_, ball_radius_, race_radius, groove_radius), E_eff,
            AreaModel::Exact),
      G_eff(G_eff_),
      beta(restitution_beta(restitution)),
      friction(friction_),
      kt_coef(8.0 * G_eff_ * hertz.ellipse(1.0).c * std::cbrt(hertz.stiffness_constant()))
{
  if (!(G_eff_ > 0.0)) throw std::invalid_argument("shear modulus must be positive");
  if (!(friction_ >= 0.0)) throw std::invalid_argument("friction coefficient must be >= 0");
}

}  // namespace ohmdem
