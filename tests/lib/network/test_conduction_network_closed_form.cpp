// SPDX-License-Identifier: GPL-2.0-or-later
// Networks with a closed-form resistance: series, parallel, Wheatstone bridge, ladder, and
// the bearing (one resistor per ball, with and without series contact resistances).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conduction/conductance_laws.h"
#include "network/conduction_network.h"
#include "test_constants.h"

using namespace ohmdem;

namespace {

const NodeKey H = 1000, L = 2000;

SolverOptions no_reduction(SolverKind kind)
{
  SolverOptions o;
  o.kind = kind;
  o.reduce_series = false;
  return o;
}

}  // namespace

TEST(ClosedForm, SeriesChain)
{
  // R = sum of the resistances (Ohm, series), summed in long double.
  std::vector<double> r;
  for (int k = 0; k < 50; ++k) r.push_back(0.1 + 0.37 * k + 1e-3 * k * k);
  long double ref = 0;
  for (double x : r) ref += x;
  for (auto kind : {SolverKind::Auto, SolverKind::Direct, SolverKind::ConjugateGradient})
    for (bool reduce : {true, false}) {
      ConductionNetwork net;
      SolverOptions o = no_reduction(kind);
      o.reduce_series = reduce;
      net.set_options(o);
      net.set_electrodes(H, L);
      NodeKey prev = H;
      for (std::size_t k = 0; k < r.size(); ++k) {
        const NodeKey next = k + 1 == r.size() ? L : 77 * k + 5;
        net.add_conductance(prev, next, 1.0 / r[k]);
        prev = next;
      }
      const NetworkSolution s = net.solve(0.1);
      EXPECT_NEAR(s.resistance, double(ref), 1e-12 * double(ref));
      EXPECT_NEAR(s.voltage_drop, 0.1 * double(ref), 1e-12 * 0.1 * double(ref));
      if (reduce) {  // the whole chain is two resistors in series repeated: no matrix
        EXPECT_EQ(s.method, SolveMethod::ClosedForm);
        EXPECT_EQ(s.unknowns, 0);
        EXPECT_EQ(s.eliminated_nodes, 49);
      } else {
        EXPECT_EQ(s.unknowns, 50);
      }
      // The potential falls linearly with the accumulated resistance along the chain. CG
      // potentials are only as good as its stopping test (R is better: see the doc).
      const double v5 = 0.1 * (double(ref) - r[0]);
      const double tol = kind == SolverKind::ConjugateGradient && !reduce ? 1e-9 : 1e-12;
      EXPECT_NEAR(net.potential(5), v5, tol * v5);
    }
}

TEST(ClosedForm, Parallel)
{
  // R = 1 / sum(g).
  ConductionNetwork net;
  net.set_electrodes(H, L);
  long double gsum = 0;
  for (int k = 1; k <= 13; ++k) {
    net.add_conductance(k % 2 ? H : L, k % 2 ? L : H, 0.5 * k);  // both orientations
    gsum += 0.5L * k;
  }
  const NetworkSolution s = net.solve(0.1);
  EXPECT_EQ(s.method, SolveMethod::ClosedForm);
  EXPECT_NEAR(s.resistance, double(1 / gsum), 1e-15);
  EXPECT_EQ(s.conducting_edges, 13);
  EXPECT_EQ(s.relative_residual, 0.0);
}

TEST(ClosedForm, WheatstoneBridge)
{
  // R1 = H-A, R2 = H-B, R3 = A-L, R4 = B-L, R5 = A-B (bridge). Standard result (e.g. by a
  // delta-star transform), checked against numpy.linalg.solve: R = [R1 R2 (R3+R4) +
  // R3 R4 (R1+R2) + R5 (R1+R3)(R2+R4)] / [R5 (R1+R2+R3+R4) + (R1+R2)(R3+R4)];
  // for (1, 2, 3, 5, 7) ohm that is 257/101.
  const NodeKey A = 11, B = 12;
  auto bridge = [&](double R1, double R2, double R3, double R4, double R5, SolverKind kind) {
    ConductionNetwork net;
    net.set_options(no_reduction(kind));
    net.set_electrodes(H, L);
    net.add_conductance(H, A, 1 / R1);
    net.add_conductance(H, B, 1 / R2);
    net.add_conductance(A, L, 1 / R3);
    net.add_conductance(B, L, 1 / R4);
    net.add_conductance(A, B, 1 / R5);
    return net.solve(1.0).resistance;
  };
  auto formula = [](double R1, double R2, double R3, double R4, double R5) {
    return (R1 * R2 * (R3 + R4) + R3 * R4 * (R1 + R2) + R5 * (R1 + R3) * (R2 + R4)) /
           (R5 * (R1 + R2 + R3 + R4) + (R1 + R2) * (R3 + R4));
  };
  for (auto kind : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
    EXPECT_NEAR(bridge(1, 2, 3, 5, 7, kind), 257.0 / 101.0, 1e-12);
    EXPECT_NEAR(bridge(1e-3, 2e3, 3, 5e5, 7e-2, kind), formula(1e-3, 2e3, 3, 5e5, 7e-2),
                1e-12 * formula(1e-3, 2e3, 3, 5e5, 7e-2));
    // Balanced (R1/R3 = R2/R4): no current in R5, R = (R1+R3) || (R2+R4) = 4*8/12.
    EXPECT_NEAR(bridge(1, 2, 3, 6, 123, kind), 4.0 * 8.0 / 12.0, 1e-12);
  }
}

TEST(ClosedForm, LadderReducesCompletely)
{
  // Top rail a0 = H, a1..aN with series r; a rung R from each ak (k >= 1) to L. Recursion
  // from the far end: Z_N = R, Z_k = R || (r + Z_{k+1}); R_total = r + Z_1.
  const int N = 200;
  const double r = 0.3, R = 7.0;
  long double Z = R;
  for (int k = N - 1; k >= 1; --k) Z = 1 / (1 / (long double)R + 1 / (r + Z));
  const double ref = double(r + Z);
  for (bool reduce : {true, false}) {
    ConductionNetwork net;
    SolverOptions o;
    o.reduce_series = reduce;
    net.set_options(o);
    net.set_electrodes(H, L);
    for (int k = 0; k < N; ++k) net.add_conductance(k == 0 ? H : NodeKey(k), NodeKey(k + 1), 1 / r);
    for (int k = 1; k <= N; ++k) net.add_conductance(NodeKey(k), L, 1 / R);
    const NetworkSolution s = net.solve(1.0);
    EXPECT_NEAR(s.resistance, ref, 1e-12 * ref);
    if (reduce) {
      EXPECT_EQ(s.method, SolveMethod::ClosedForm);
    }
  }
}

TEST(ClosedForm, BearingIsOneResistorPerBall)
{
  // 13 balls, each touching the outer race (H) and the inner race (L) at opposite points:
  // eq. 1 with theta = pi gives g_k = gamma S_o S_i / (4 V); R = 1 / sum g_k.
  const double rb = 6.3e-3, V = sphere_volume(rb), gamma = 5.88e7;
  ConductionNetwork net;
  net.set_electrodes(H, L);
  long double gsum = 0;
  for (int k = 0; k < 13; ++k) {
    const double phi = 2 * test::kPi * k / 13, c = std::cos(phi), s = std::sin(phi);
    const double So = 1e-7 * (1 + 0.01 * k), Si = 0.8e-7 * (1 + 0.02 * k);
    ConductingParticle p{{0.0301 * c, 0.0301 * s, 0}, rb, V, gamma};
    std::vector<ContactSpot> spots = {{H, {(0.0301 + rb) * c, (0.0301 + rb) * s, 0}, So},
                                      {L, {(0.0301 - rb) * c, (0.0301 - rb) * s, 0}, Si}};
    add_particle_conductances(net, p, spots.data(), spots.size());
    gsum += (long double)gamma * So * Si / (4 * (long double)V);
  }
  const NetworkSolution s = net.solve(0.1);
  EXPECT_EQ(s.method, SolveMethod::ClosedForm);
  EXPECT_EQ(s.unknowns, 0);
  EXPECT_NEAR(s.resistance, double(1 / gsum), 1e-12 * double(1 / gsum));
  // One ball losing its contact (a defect) removes its conductance.
  ConductionNetwork broken;
  broken.set_electrodes(H, L);
  const std::vector<NetworkEdge> all = net.edges();
  ASSERT_EQ(all.size(), 13u);
  for (std::size_t k = 1; k < all.size(); ++k)
    broken.add_conductance(all[k].a, all[k].b, all[k].conductance);
  EXPECT_NEAR(broken.solve(0.1).resistance, double(1 / (gsum - all[0].conductance)),
              1e-12 * s.resistance);
}

TEST(ClosedForm, BearingWithSeriesContactResistances)
{
  // Holm model: each contact is split into two nodes joined by 1/R_c (contact_side_key).
  // Ball k: H -(g_o)- outer side -(g_b)- inner side -(g_i)- L, series reduction gives
  // R = 1 / sum_k 1/(1/g_o + 1/g_b + 1/g_i), again without a matrix.
  ConductionNetwork net;
  net.set_electrodes(H, L);
  long double gsum = 0;
  for (std::uint32_t k = 1; k <= 13; ++k) {
    const double go = 2e4 * k, gb = 0.14 + 0.001 * k, gi = 3e4 / k;
    const NodeKey outer_side = contact_side_key(k, 0xFFFFFFF0u);  // ball k's side, outer race
    const NodeKey inner_side = contact_side_key(k, 0xFFFFFFF1u);
    net.add_conductance(H, outer_side, go);
    net.add_conductance(outer_side, inner_side, gb);
    net.add_conductance(inner_side, L, gi);
    gsum += 1 / (1 / (long double)go + 1 / (long double)gb + 1 / (long double)gi);
  }
  const NetworkSolution s = net.solve(0.1);
  EXPECT_EQ(s.method, SolveMethod::ClosedForm);
  EXPECT_EQ(s.eliminated_nodes, 26);
  EXPECT_NEAR(s.resistance, double(1 / gsum), 1e-13 * double(1 / gsum));
  // Potentials of the split nodes are recovered exactly: V = I * R_below along each ball.
  const double go = 2e4, gb = 0.141, gi = 3e4;
  const double i1 = 0.1 * s.resistance / (1 / go + 1 / gb + 1 / gi);  // current of ball 1
  EXPECT_NEAR(net.potential(contact_side_key(1, 0xFFFFFFF1u)), i1 / gi, 1e-15);
  EXPECT_NEAR(net.potential(contact_side_key(1, 0xFFFFFFF0u)), i1 * (1 / gi + 1 / gb), 1e-13);
}
