// SPDX-License-Identifier: GPL-2.0-or-later
// Per-contact rows of a solved network (conduction/contact_flows.h): a chain against eq. 1
// written out here, Kirchhoff and Ohm on a branched scene for every model, the bearing closed
// form's rows against the general network's.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "conduction/conduction_model.h"
#include "conduction/contact_flows.h"
#include "conduction/network_builder.h"
#include "test_constants.h"

using namespace ohmdem;

namespace {

constexpr double kGamma = 5.88e7;  // steel (S/m), paper Table 2
constexpr double kR = 5e-3;        // particle radius (m)
constexpr double kI = 0.1;         // injected current (A)

struct Case {
  std::vector<ParticleRecord> particles;
  std::vector<ContactRecord> contacts;
  std::vector<double> gamma_type{0.0, kGamma};
  std::vector<double> gamma_race{kGamma, kGamma};
  ConductionNetwork net;
  NetworkBuild built;
  std::vector<ContactFlow> rows;
  double resistance = 0;

  void solve(const ConductionModel &m)
  {
    build_network(m, {&particles, &contacts, &gamma_type, &gamma_race, false}, net, built);
    net.set_electrodes(race_node(0), race_node(1));
    resistance = net.solve(kI).resistance;
    network_contact_flows(m, {&particles, &contacts, &gamma_type, &gamma_race, false}, built, net,
                          rows);
  }
};

// Particles 1..n on the x axis, touching; race 0 left of particle 1, race 1 right of n.
// Contact radius c on every spot (a circle: a = b = c).
Case chain(int n, double c)
{
  Case k;
  for (int t = 1; t <= n; ++t)
    k.particles.push_back({t, {2.0 * kR * t, 0.0, 0.0}, kR, 1, Membership::None});
  k.contacts.push_back({1, 0, 0, 1.0, {2.0 * kR - kR, 0, 0}, c, c});
  for (int t = 1; t < n; ++t)
    k.contacts.push_back({t + 1, t, -1, 1.0, {2.0 * kR * t + kR, 0, 0}, c, c});  // owner t + 1
  k.contacts.push_back({n, 0, 1, 1.0, {2.0 * kR * n + kR, 0, 0}, c, c});
  return k;
}

// Currents into each particle and through each electrode, from the rows alone.
void expect_kirchhoff(const std::vector<ContactFlow> &rows, double tol)
{
  std::map<std::int64_t, double> into;
  double high = 0, low = 0;
  for (const ContactFlow &r : rows) {
    into[r.atom] += r.current;
    if (r.partner) into[r.partner] -= r.current;
    if (r.electrode == 1) high += r.current;
    if (r.electrode == -1) low -= r.current;
    EXPECT_NEAR(r.conductance * r.drop, r.current, tol * kI);
    EXPECT_TRUE(r.partner == 0 || r.atom < r.partner);
  }
  for (const auto &[tag, sum] : into) EXPECT_NEAR(sum, 0.0, tol * kI) << "particle " << tag;
  EXPECT_NEAR(high, kI, tol * kI);
  EXPECT_NEAR(low, kI, tol * kI);
}

}  // namespace

// Eq. 1 for two opposite spots (theta = pi, 1 - cos = 2): g = gamma S^2 / (4 V), the chain's
// particles in series; every row carries I, its drop is I / g.
TEST(ContactFlows, ChainAgainstEq1WrittenOut)
{
  const double c = 1e-4, s = test::kPi * c * c, v = 4.0 / 3.0 * test::kPi * kR * kR * kR;
  const double g = kGamma * s * s / (4.0 * v);
  Case k = chain(3, c);
  ConductionModel m;
  ASSERT_TRUE(find_model("eq1", m));
  k.solve(m);
  EXPECT_NEAR(k.resistance * g / 3.0, 1.0, 1e-12);
  ASSERT_EQ(k.rows.size(), 4u);  // race-1, 1-2, 2-3, 3-race
  for (const ContactFlow &r : k.rows) {
    EXPECT_NEAR(r.conductance / g, 1.0, 1e-12);
    // From the partner into the atom: +I from the high race; the current flows 1 -> 2 -> 3,
    // so into the smaller ID of a pair, and from the low race, it is -I.
    const double expect = r.electrode == 1 ? kI : -kI;
    EXPECT_NEAR(r.current / expect, 1.0, 1e-12);
    EXPECT_NEAR(r.drop / (expect / g), 1.0, 1e-12);
    EXPECT_EQ(r.masked, 0);
  }
  expect_kirchhoff(k.rows, 1e-12);
}

// A branched scene (a 3 x 3 grid of particles, each touching its neighbours; the left column
// on race 0, the right one on race 1; spot sizes all different): Kirchhoff and Ohm for every
// model of the table.
TEST(ContactFlows, KirchhoffOnAGridForEveryModel)
{
  for (const ModelEntry &e : model_table()) {
    Case k;
    auto tag = [](int i, int j) { return std::int64_t(1 + i + 3 * j); };
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        k.particles.push_back(
            {tag(i, j), {2.0 * kR * i, 2.0 * kR * j, 0.0}, kR, 1, Membership::None});
    double c = 5e-5;
    auto next_c = [&c] { return c *= 1.07; };
    for (int j = 0; j < 3; ++j) {
      k.contacts.push_back({tag(0, j), 0, 0, 1.0, {-kR, 2.0 * kR * j, 0}, next_c(), c});
      k.contacts.push_back({tag(2, j), 0, 1, 1.0, {5.0 * kR, 2.0 * kR * j, 0}, next_c(), c});
      for (int i = 0; i < 3; ++i) {
        if (i < 2)
          k.contacts.push_back({tag(i + 1, j),
                                tag(i, j),
                                -1,
                                1.0,
                                {2.0 * kR * i + kR, 2.0 * kR * j, 0},
                                next_c(),
                                c});
        if (j < 2)
          k.contacts.push_back({tag(i, j),
                                tag(i, j + 1),
                                -1,
                                1.0,
                                {2.0 * kR * i, 2.0 * kR * j + kR, 0},
                                next_c(),
                                c});
      }
    }
    k.solve(e.model);
    EXPECT_EQ(k.rows.size(), k.contacts.size()) << e.name;
    expect_kirchhoff(k.rows, 1e-10);
  }
}

// The closed form's two rows of a ball: +I_ball from the high race, -I_ball into the low one,
// G drop = current on each; with constrictions the drops are those of the two spots.
TEST(ContactFlows, BallBetweenRaces)
{
  ContactFlow two[2];
  ball_between_races_flows(7, 0.5, 0.2, false, 0.0, 0.0, two);
  EXPECT_EQ(two[0].atom, 7);
  EXPECT_EQ(two[0].electrode, 1);
  EXPECT_EQ(two[1].electrode, -1);
  EXPECT_DOUBLE_EQ(two[0].current, 0.1);
  EXPECT_DOUBLE_EQ(two[1].current, -0.1);
  EXPECT_DOUBLE_EQ(two[0].drop, 0.2);
  EXPECT_DOUBLE_EQ(two[0].conductance, 0.5);
  ball_between_races_flows(7, 0.5, 0.2, true, 0.25, 1.0, two);
  EXPECT_DOUBLE_EQ(two[0].conductance, 4.0);
  EXPECT_DOUBLE_EQ(two[0].drop, 0.025);
  EXPECT_DOUBLE_EQ(two[1].conductance, 1.0);
  EXPECT_DOUBLE_EQ(two[1].drop, -0.1);
  const ContactFlow masked = idle_race_flow(3, -1, 2.0, true);
  EXPECT_EQ(masked.masked, 1);
  EXPECT_EQ(masked.conductance, 0.0);
  EXPECT_EQ(idle_race_flow(3, 1, 2.0, false).conductance, 0.5);
}
