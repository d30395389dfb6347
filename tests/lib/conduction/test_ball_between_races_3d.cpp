// SPDX-License-Identifier: GPL-2.0-or-later
// The 3D bearing's ball between two races (src_fix/lib/conduction/ball_between_races_3d.*): in
// the bearing plane (contact angle 0) it is the closed form BallBetweenRaces for every row of the
// model table; off the plane it is eq. 1 with the angle between the contact points in space and
// Holm's ellipses, written out here from the paper and Holm.
#include <gtest/gtest.h>

#include <cmath>

#include "conduction/ball_between_races_3d.h"
#include "conduction/conduction_model.h"
#include "contact/torus_race.h"
#include "test_constants.h"

namespace {

using ohmdem::test::kPi;

constexpr double kRb = 6.3e-3, kGamma = 5.88e7, kEstar = 200e9 / (2 * (1 - 0.09));

ohmdem::AngularHertz hertz(ohmdem::RaceSide side)
{
  ohmdem::TorusGroove g;
  g.side = side;
  g.ball_radius = kRb;
  g.groove_radius = side == ohmdem::RaceSide::Inner ? 6.55e-3 : 6.65e-3;
  g.centre_radius = side == ohmdem::RaceSide::Inner ? 24e-3 + 6.55e-3 : 36.6e-3 - 6.65e-3;
  return ohmdem::AngularHertz(g, kEstar, 7e10, 3.8e10);
}

}  // namespace

TEST(BallBetweenRaces3d, InThePlaneItIsTheClosedForm)
{
  const auto hi = hertz(ohmdem::RaceSide::Outer), lo = hertz(ohmdem::RaceSide::Inner);
  for (const auto &row : ohmdem::model_table()) {
    for (auto area : {ohmdem::AreaModel::Greenwood, ohmdem::AreaModel::Exact}) {
      const ohmdem::HertzContact h2(ohmdem::torus_curvatures(hi.groove(), 1.0), kEstar, area);
      const ohmdem::HertzContact l2(ohmdem::torus_curvatures(lo.groove(), 1.0), kEstar, area);
      const ohmdem::BallBetweenRaces planar(row.model, h2, l2, kGamma, kGamma, {0.0, kGamma});
      const double fh = 120.0, fl = 130.0;
      const double u[3] = {kRb * 0.8, kRb * 0.6, 0.0}, w[3] = {-kRb * 0.8, -kRb * 0.6, 0.0};
      const double g2 = planar.conductance(1, kGamma, kRb, fh, fl, u, w);
      const auto r =
          ohmdem::ball_resistances_3d(row.model, kGamma, kRb, kGamma, kGamma,
                                      hi.ellipse(1.0, fh, area), lo.ellipse(1.0, fl, area), u, w);
      EXPECT_NEAR(1.0 / r.total() / g2, 1.0, 1e-9) << row.name;
    }
  }
}

TEST(BallBetweenRaces3d, OffThePlaneEq1AndHolmAsWritten)
{
  // Contact points at +-alpha off the plane, not facing each other exactly.
  const auto hi = hertz(ohmdem::RaceSide::Outer), lo = hertz(ohmdem::RaceSide::Inner);
  const double a_hi = 0.31, a_lo = 0.27, fh = 200.0, fl = 210.0;
  const double u[3] = {kRb * std::cos(a_hi), 0.0, kRb * std::sin(a_hi)};
  const double w[3] = {-kRb * std::cos(a_lo), 0.0, -kRb * std::sin(a_lo)};
  const auto eh = hi.ellipse(std::cos(a_hi), fh, ohmdem::AreaModel::Exact);
  const auto el = lo.ellipse(std::cos(a_lo), fl, ohmdem::AreaModel::Exact);
  ohmdem::ConductionModel m;
  ohmdem::find_model("eq1+holm", m);
  const auto r = ohmdem::ball_resistances_3d(m, kGamma, kRb, kGamma, kGamma, eh, el, u, w);
  // Paper eq. 1: C = gamma S_i S_j / (2 V (1 - cos theta)), theta = pi - (a_lo - a_hi).
  const double theta = kPi - (a_lo - a_hi), V = 4.0 / 3 * kPi * kRb * kRb * kRb;
  const double eq1 = kGamma * eh.area * el.area / (2 * V * (1 - std::cos(theta)));
  EXPECT_NEAR(r.bulk * eq1, 1.0, 1e-12);
  // Holm: rho K(e^2) / (pi a), rho = 1/gamma for one steel, e^2 = 1 - (b/a)^2.
  const double holm =
      1 / kGamma * std::comp_ellint_1(std::sqrt(1 - eh.b * eh.b / (eh.a * eh.a))) / (kPi * eh.a);
  EXPECT_NEAR(r.hi / holm, 1.0, 1e-12);
}
