// SPDX-License-Identifier: GPL-2.0-or-later
// Paper eq. 1 conductance, the small-angle clamp and the per-particle helper.
// Reference numbers: hand calculation with Python's math module (formula in the comments).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conduction/conductance_laws.h"
#include "test_constants.h"

using namespace ohmdem;

namespace {
const double kGamma = 5.88e7;  // S/m, paper Table 2
const double kRb = 6.3e-3;     // m, ball radius of the 6208 (Db = 12.6 mm)
}  // namespace

TEST(Eq1, HandCalculation)
{
  const double V = sphere_volume(kRb);
  // 4/3*pi*6.3e-3**3
  EXPECT_NEAR(V, 1.0473944243362228e-06, 1e-15 * V);
  // 5.88e7*2e-8*3e-8/(2*V*(1-cos(theta))) for theta = pi/2, pi, pi/3
  const double cases[3][2] = {{test::kPi / 2, 0.016841792919777283},
                              {test::kPi, 0.00842089645988864},
                              {test::kPi / 3, 0.03368358583955457}};
  for (const auto &c : cases) {
    const Eq1Result r = eq1_conductance(kGamma, 2e-8, 3e-8, V, c[0], kRb);
    EXPECT_NEAR(r.conductance, c[1], 1e-13 * c[1]) << "theta = " << c[0];
    EXPECT_FALSE(r.clamped);
    EXPECT_EQ(r.theta, c[0]);
  }
}

TEST(Eq1, AngleBetweenIsAccurateNearZeroAndPi)
{
  const double x[3] = {1, 0, 0}, y[3] = {0, 2, 0}, mx[3] = {-3, 0, 0}, zero[3] = {0, 0, 0};
  EXPECT_DOUBLE_EQ(angle_between(x, y), test::kPi / 2);
  EXPECT_DOUBLE_EQ(angle_between(x, mx), test::kPi);
  EXPECT_EQ(angle_between(x, x), 0.0);
  EXPECT_EQ(angle_between(x, zero), 0.0);
  // acos(cos(1e-9)) returns 0 in double; atan2 keeps the angle (relative 1e-15).
  const double t = 1e-9, u[3] = {std::cos(t), std::sin(t), 0};
  EXPECT_NEAR(angle_between(x, u), t, 1e-15 * t);
}

TEST(Eq1, SmallAngleClampIsBoundedAndContinuous)
{
  const double V = sphere_volume(kRb), Si = 2e-8, Sj = 3e-8;
  // (sqrt(Si/pi) + sqrt(Sj/pi)) / r
  const double tmin = min_spot_angle(Si, Sj, kRb);
  EXPECT_NEAR(tmin, 0.02817602515251913, 1e-14);
  // 5.88e7*Si*Sj/(2*V*(1-cos(tmin)))
  const double gmax = 42.43142313903659;
  for (double theta : {0.0, 1e-12, 1e-6, 0.5 * tmin, tmin * (1 - 1e-12)}) {
    const Eq1Result r = eq1_conductance(kGamma, Si, Sj, V, theta, kRb);
    EXPECT_TRUE(r.clamped) << theta;
    EXPECT_EQ(r.theta, tmin);
    EXPECT_NEAR(r.conductance, gmax, 1e-12 * gmax);
    EXPECT_TRUE(std::isfinite(r.conductance));
  }
  // Continuous at tmin, and never larger than gmax above it.
  const Eq1Result above = eq1_conductance(kGamma, Si, Sj, V, tmin * (1 + 1e-9), kRb);
  EXPECT_FALSE(above.clamped);
  EXPECT_NEAR(above.conductance, gmax, 1e-8 * gmax);
  EXPECT_LT(above.conductance, gmax);
  // Spots so large they cover the sphere: the bound saturates at pi, 1 - cos = 2.
  EXPECT_EQ(min_spot_angle(1.0, 1.0, 1e-3), test::kPi);
  const Eq1Result huge = eq1_conductance(kGamma, 1.0, 1.0, V, 0.0, 1e-3);
  EXPECT_NEAR(huge.conductance, kGamma / (4 * V), 1e-14 * kGamma / V);
}

TEST(Eq1, DegenerateInputsGiveZeroNotNaN)
{
  const double V = sphere_volume(kRb);
  EXPECT_EQ(eq1_conductance(kGamma, 0.0, 1e-8, V, 1.0, kRb).conductance, 0.0);
  EXPECT_EQ(eq1_conductance(0.0, 1e-8, 1e-8, V, 1.0, kRb).conductance, 0.0);  // insulator
  EXPECT_EQ(eq1_conductance(kGamma, 1e-8, 1e-8, 0.0, 1.0, kRb).conductance, 0.0);
  EXPECT_EQ(eq1_conductance(kGamma, 1e-8, 1e-8, V, 1.0, 0.0).conductance, 0.0);
  EXPECT_EQ(eq1_conductance(kGamma, NAN, 1e-8, V, 1.0, kRb).conductance, 0.0);
  EXPECT_EQ(eq1_conductance(kGamma, 1e-8, 1e-8, V, NAN, kRb).conductance, 0.0);
}

TEST(Eq1, SeriesConductance)
{
  EXPECT_DOUBLE_EQ(series_conductance(2.0, 2.0), 1.0);   // 1/(1/2+1/2)
  EXPECT_DOUBLE_EQ(series_conductance(1.0, 3.0), 0.75);  // 1/(1+1/3)
  EXPECT_EQ(series_conductance(INFINITY, 3.0), 3.0);     // a perfect conductor adds nothing
  EXPECT_EQ(series_conductance(0.0, 3.0), 0.0);          // an open contact breaks the path
}

TEST(Eq1, ParticleHelperAddsEveryPairOnce)
{
  const double r = 1e-3, V = sphere_volume(r);
  ConductingParticle p{{1, 2, 3}, r, V, kGamma};
  // Three spots at +x, +y, -x from the centre (1, 2, 3).
  std::vector<ContactSpot> s = {
      {10, {1 + r, 2, 3}, 1e-8}, {11, {1, 2 + r, 3}, 2e-8}, {12, {1 - r, 2, 3}, 1e-8}};
  ConductionNetwork net;
  EXPECT_EQ(add_particle_conductances(net, p, s.data(), s.size()), 0);
  const std::vector<NetworkEdge> e = net.edges();
  ASSERT_EQ(e.size(), 3u);
  // canonical order (10,11), (10,12), (11,12); angles pi/2, pi, pi/2
  EXPECT_DOUBLE_EQ(e[0].conductance, kGamma * 1e-8 * 2e-8 / (2 * V * 1.0));
  EXPECT_DOUBLE_EQ(e[1].conductance, kGamma * 1e-8 * 1e-8 / (2 * V * 2.0));
  EXPECT_DOUBLE_EQ(e[2].conductance, kGamma * 2e-8 * 1e-8 / (2 * V * 1.0));
}

TEST(Eq1, ParticleHelperSkipsPairsOnOneElectrode)
{
  // A plate particle touching the plate at two points plus one particle: the two plate
  // contacts are one node, so only the two plate-particle pairs remain (parallel, same node).
  const double r = 1e-3;
  ConductingParticle p{{0, 0, 0}, r, sphere_volume(r), kGamma};
  std::vector<ContactSpot> s = {{7, {0, -r, 0}, 1e-8}, {7, {r, 0, 0}, 1e-8}, {9, {0, r, 0}, 1e-8}};
  ConductionNetwork net;
  add_particle_conductances(net, p, s.data(), s.size());
  EXPECT_EQ(net.num_edges(), 2u);
  net.set_electrodes(9, 7);
  const NetworkSolution sol = net.solve(1.0);
  EXPECT_EQ(sol.self_loops, 0);
  // two parallel edges, angles pi and pi/2: g = gamma S^2/(2V) * (1/2 + 1)
  const double g = kGamma * 1e-16 / (2 * sphere_volume(r)) * 1.5;
  EXPECT_NEAR(sol.resistance, 1.0 / g, 1e-14 / g);
}
