// SPDX-License-Identifier: GPL-2.0-or-later
// The conduction model: its composition table, and closed form == network on the same balls
// for every row of the table (the bearing's two evaluations of one model).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "conduction/conduction_model.h"
#include "conduction/network_builder.h"
#include "contact/hertz_contact.h"
#include "test_constants.h"

using namespace ohmdem;

namespace {

// SKF 6208 (paper Tables 1-2, doc/methods/hertz_contact.md "SKF 6208"): ball radius, race radii,
// groove radii (m); steel E = 200 GPa, nu = 0.3; gamma = 5.88e7 S/m (paper Table 2).
constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
constexpr double kGamma = 5.88e7;
const double kEstar = effective_modulus(200e9, 0.3, 200e9, 0.3);

struct Ball {
  double angle;    // position on the pitch circle (rad)
  double fn_hi;    // N, on the outer race (high electrode)
  double fn_lo;    // N, on the inner race (low electrode)
  double tilt_lo;  // rotation of the inner contact point about the ball centre (rad): 0 = facing
  int type;
};

struct Scene {
  HertzContact outer{ball_outer_race(kRb, kRext, kRcExt), kEstar, AreaModel::Greenwood};
  HertzContact inner{ball_inner_race(kRb, kRinn, kRcInn), kEstar, AreaModel::Greenwood};
  std::vector<double> gamma_type{0.0, kGamma, 0.5 * kGamma};  // 1-based
  double gamma_hi = kGamma, gamma_lo = 2.0 * kGamma;
  std::vector<Ball> balls;
};

Scene bearing(bool with_acute)
{
  Scene s;
  const int n = 13;
  for (int k = 0; k < n; ++k) {
    const double q = 60.0 + 25.0 * std::cos(2.0 * test::kPi * k / n) + 3.0 * k;
    s.balls.push_back({2.0 * test::kPi * k / n, q, 1.1 * q, 0.0, 1 + k % 2});
  }
  if (with_acute) {
    s.balls[3].tilt_lo = 2.0;  // 115 degrees from facing: an acute angle between the spots
    s.balls[7].tilt_lo = 0.4;  // obtuse, not facing
    s.balls[9].tilt_lo = 3.1;  // nearly coincident spots: eq. 1's small-angle bound applies
  }
  return s;
}

struct Points {
  double centre[3], hi[3], lo[3];
};

Points points_of(const Ball &b)
{
  const double rp = 0.5 * (kRext + kRinn);
  Points p{};
  const double c = std::cos(b.angle), s = std::sin(b.angle);
  p.centre[0] = rp * c;
  p.centre[1] = rp * s;
  p.hi[0] = p.centre[0] + kRb * c;  // outer race: away from the axis
  p.hi[1] = p.centre[1] + kRb * s;
  const double t = b.angle + test::kPi + b.tilt_lo;  // inner race: toward the axis, maybe tilted
  p.lo[0] = p.centre[0] + kRb * std::cos(t);
  p.lo[1] = p.centre[1] + kRb * std::sin(t);
  return p;
}

double closed_form_R(const ConductionModel &m, const Scene &s)
{
  const BallBetweenRaces model(m, s.outer, s.inner, s.gamma_hi, s.gamma_lo, s.gamma_type);
  double g = 0.0;
  for (const Ball &b : s.balls) {
    const Points p = points_of(b);
    const double u[3] = {p.hi[0] - p.centre[0], p.hi[1] - p.centre[1], 0.0};
    const double w[3] = {p.lo[0] - p.centre[0], p.lo[1] - p.centre[1], 0.0};
    g += model.conductance(b.type, s.gamma_type[b.type], kRb, b.fn_hi, b.fn_lo, u, w);
  }
  return 1.0 / g;
}

double network_R(const ConductionModel &m, const Scene &s)
{
  std::vector<ParticleRecord> particles;
  std::vector<ContactRecord> contacts;
  std::int64_t tag = 1;
  for (const Ball &b : s.balls) {
    const Points p = points_of(b);
    particles.push_back({tag, {p.centre[0], p.centre[1], 0.0}, kRb, b.type, Membership::None});
    const auto eh = s.outer.ellipse(b.fn_hi), el = s.inner.ellipse(b.fn_lo);
    contacts.push_back({tag, 0, 0, b.fn_hi, {p.hi[0], p.hi[1], 0.0}, eh.a, eh.b});
    contacts.push_back({tag, 0, 1, b.fn_lo, {p.lo[0], p.lo[1], 0.0}, el.a, el.b});
    ++tag;
  }
  const std::vector<double> gamma_race{s.gamma_hi, s.gamma_lo};
  ConductionNetwork net;
  NetworkBuild built;
  build_network(m, {&particles, &contacts, &s.gamma_type, &gamma_race, false}, net, built);
  net.set_electrodes(race_node(0), race_node(1));
  return net.solve(0.1).resistance;
}

}  // namespace

TEST(ConductionModel, CompositionTable)
{
  ConductionModel m;
  ASSERT_TRUE(find_model("eq1", m));
  EXPECT_TRUE(m.has_bulk() && !m.has_constriction());
  ASSERT_TRUE(find_model("holm", m));
  EXPECT_TRUE(!m.has_bulk() && m.has_constriction());
  ASSERT_TRUE(find_model("eq1+holm", m));
  EXPECT_TRUE(m.has_bulk() && m.has_constriction());
  EXPECT_FALSE(find_model("ohm", m));
  EXPECT_TRUE(m.has_bulk() && m.has_constriction());  // untouched by a failed lookup
  EXPECT_EQ(model_names(), "eq1, holm or eq1+holm");
  // Without a constriction slot a spot has no resistance; with Holm, rho/(2a) for a circle
  // (Holm 1967) with rho the mean of the two resistivities.
  ASSERT_TRUE(find_model("eq1", m));
  EXPECT_EQ(m.constriction_resistance(kGamma, kGamma, 1e-4, 1e-4), 0.0);
  ASSERT_TRUE(find_model("holm", m));
  const double rho = 0.5 * (1.0 / kGamma + 1.0 / (2.0 * kGamma));
  EXPECT_NEAR(m.constriction_resistance(kGamma, 2.0 * kGamma, 1e-4, 1e-4) / (rho / 2e-4), 1.0,
              1e-14);
}

// Both evaluations of the model on the same 13 balls, for every row of the table: the balls
// facing their two races (the closed form's fast paths), and with three balls whose spots are
// not opposite (the general path, including eq. 1's small-angle bound).
TEST(ConductionModel, ClosedFormEqualsNetworkForEveryModel)
{
  for (bool acute : {false, true}) {
    const Scene s = bearing(acute);
    for (const ModelEntry &e : model_table()) {
      const double closed = closed_form_R(e.model, s), general = network_R(e.model, s);
      ASSERT_TRUE(std::isfinite(closed) && closed > 0.0) << e.name;
      EXPECT_NEAR(closed / general, 1.0, 1e-12)
          << e.name << (acute ? ", spots not facing" : ", spots facing") << ": closed form "
          << closed << " ohm, network " << general << " ohm";
    }
  }
}

// eq. 1 written out for one facing ball: C = gamma S_hi S_lo / (2 V (1 - cos pi)).
TEST(ConductionModel, ClosedFormIsEq1ForOneFacingBall)
{
  Scene s = bearing(false);
  s.balls.resize(1);
  ConductionModel m;
  ASSERT_TRUE(find_model("eq1", m));
  const Ball &b = s.balls[0];
  const double S_hi = s.outer.ellipse(b.fn_hi).area, S_lo = s.inner.ellipse(b.fn_lo).area;
  const double V = 4.0 / 3.0 * test::kPi * kRb * kRb * kRb;
  const double ref = 1.0 / (kGamma * S_hi * S_lo / (2.0 * V * 2.0));
  EXPECT_NEAR(closed_form_R(m, s) / ref, 1.0, 1e-13);
}

// With an insulating race nothing conducts: R = inf on both paths.
TEST(ConductionModel, InsulatingRaceGivesNoPath)
{
  Scene s = bearing(false);
  s.gamma_lo = 0.0;
  for (const ModelEntry &e : model_table()) {
    EXPECT_TRUE(std::isinf(closed_form_R(e.model, s))) << e.name;
    EXPECT_TRUE(std::isinf(network_R(e.model, s))) << e.name;
  }
}
