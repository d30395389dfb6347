// SPDX-License-Identifier: GPL-2.0-or-later
// Hard cases: empty networks, ignored conductances, floating clusters, no path, nodes that
// lose their edges between steps, caller errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "network/conduction_network.h"

using namespace ohmdem;

namespace {

const NodeKey H = 1, L = 2;
const double kInf = std::numeric_limits<double>::infinity();

// A 2x2 grid of unit conductances between H and L with a diagonal, so that it needs a
// matrix: H-A, H-B, A-L, B-L, A-B (Wheatstone, 1 ohm each: R = 1 ohm by symmetry).
void add_bridge(ConductionNetwork &net, NodeKey A, NodeKey B)
{
  net.add_conductance(H, A, 1);
  net.add_conductance(H, B, 1);
  net.add_conductance(A, L, 1);
  net.add_conductance(B, L, 1);
  net.add_conductance(A, B, 1);
}

}  // namespace

TEST(EdgeCases, NoEdgesIsNoPath)
{
  ConductionNetwork net;
  net.set_electrodes(H, L);
  const NetworkSolution s = net.solve(0.1);
  EXPECT_FALSE(s.connected);
  EXPECT_EQ(s.resistance, kInf);
  EXPECT_EQ(s.voltage_drop, kInf);
  EXPECT_EQ(net.potential(H), 0.0);
  EXPECT_TRUE(net.edges().empty());
}

TEST(EdgeCases, SingleEdge)
{
  ConductionNetwork net;
  net.set_electrodes(H, L);
  net.add_conductance(L, H, 4.0);  // orientation does not matter
  const NetworkSolution s = net.solve(0.1);
  EXPECT_TRUE(s.connected);
  EXPECT_EQ(s.resistance, 0.25);  // 1/4, exact in binary
  EXPECT_EQ(net.potential(H), 0.025);
  EXPECT_EQ(net.potential(L), 0.0);
  const auto e = net.edges();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].a, H);  // canonical a < b
  EXPECT_DOUBLE_EQ(e[0].current, 0.1);
}

TEST(EdgeCases, InvalidConductancesAreIgnoredAndCounted)
{
  ConductionNetwork net;
  net.set_electrodes(H, L);
  net.add_conductance(H, L, 2.0);
  for (double g : {0.0, -0.0, -1.0, std::nan(""), kInf, -kInf}) net.add_conductance(H, 5, g);
  net.add_conductance(5, 5, 1.0);  // self-loop
  EXPECT_EQ(net.num_edges(), 1u);
  const NetworkSolution s = net.solve(1.0);
  EXPECT_EQ(s.ignored_conductances, 6);
  EXPECT_EQ(s.self_loops, 1);
  EXPECT_EQ(s.resistance, 0.5);
  EXPECT_FALSE(std::isnan(s.resistance));
}

TEST(EdgeCases, FloatingClusterIsDropped)
{
  // Cluster 1 holds both electrodes (bridge, R = 1); cluster 2 is a floating triangle.
  ConductionNetwork net;
  net.set_electrodes(H, L);
  add_bridge(net, 10, 11);
  net.add_conductance(20, 21, 3);
  net.add_conductance(21, 22, 3);
  net.add_conductance(22, 20, 3);
  for (auto kind : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
    const NetworkSolution s = net.solve(2.0, kind);
    EXPECT_NEAR(s.resistance, 1.0, 1e-14);
    EXPECT_EQ(s.floating_nodes_dropped, 3);
    EXPECT_EQ(s.conducting_edges, 5);
    EXPECT_EQ(net.potential(21), 0.0);
    EXPECT_FALSE(net.is_connected(21));
    EXPECT_TRUE(net.is_connected(10));
    // By symmetry A and B sit at half the drop: 1 V.
    EXPECT_NEAR(net.potential(10), 1.0, 1e-14);
    for (const NetworkEdge &e : net.edges())
      if (e.a >= 20) {
        EXPECT_EQ(e.current, 0.0);
      }
  }
}

TEST(EdgeCases, NoPathBetweenElectrodes)
{
  // H and L each in their own cluster: R = +inf, never NaN, no throw.
  ConductionNetwork net;
  net.set_electrodes(H, L);
  net.add_conductance(H, 10, 1);
  net.add_conductance(10, 11, 1);
  net.add_conductance(L, 20, 1);
  for (auto kind : {SolverKind::Auto, SolverKind::Direct, SolverKind::ConjugateGradient}) {
    const NetworkSolution s = net.solve(0.1, kind);
    EXPECT_FALSE(s.connected);
    EXPECT_EQ(s.resistance, kInf);
    EXPECT_EQ(s.floating_nodes_dropped, 5);
    EXPECT_EQ(net.potential(10), 0.0);
  }
}

TEST(EdgeCases, ElectrodeWithoutEdges)
{
  ConductionNetwork net;
  net.set_electrodes(H, 99);
  add_bridge(net, 10, 11);
  EXPECT_EQ(net.solve(1.0).resistance, kInf);
}

TEST(EdgeCases, NodeLosingAllEdges)
{
  // Step 1: bridge with a dangling branch on A. Step 2: the same contacts, but node 10 (A)
  // lost all of its contacts: H - B - L remains, R = 2.
  ConductionNetwork net;
  net.set_electrodes(H, L);
  add_bridge(net, 10, 11);
  net.add_conductance(10, 30, 5);
  NetworkSolution s = net.solve(1.0, SolverKind::ConjugateGradient);
  EXPECT_NEAR(s.resistance, 1.0, 1e-12);
  EXPECT_NEAR(net.potential(30), net.potential(10), 1e-15);  // a dangling node: no current
  net.clear();
  net.add_conductance(H, 11, 1);
  net.add_conductance(11, L, 1);
  for (auto kind : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
    s = net.solve(1.0, kind);
    EXPECT_EQ(s.resistance, 2.0);
    EXPECT_EQ(net.potential(10), 0.0);
    EXPECT_FALSE(net.is_connected(10));
    EXPECT_EQ(net.potential(30), 0.0);
  }
}

TEST(EdgeCases, ElectrodesOnOneBody)
{
  // high == low: a short circuit, R = 0 (not NaN).
  ConductionNetwork net;
  net.set_electrodes(H, H);
  net.add_conductance(H, 10, 1);
  const NetworkSolution s = net.solve(1.0);
  EXPECT_TRUE(s.connected);
  EXPECT_EQ(s.resistance, 0.0);
}

TEST(EdgeCases, NegativeCurrentFlipsPotentialsNotR)
{
  ConductionNetwork net;
  net.set_electrodes(H, L);
  add_bridge(net, 10, 11);
  const NetworkSolution s = net.solve(-0.5);
  EXPECT_NEAR(s.resistance, 1.0, 1e-14);
  EXPECT_NEAR(net.potential(H), -0.5, 1e-14);
}

TEST(EdgeCases, CallerErrorsThrow)
{
  ConductionNetwork net;
  net.add_conductance(H, L, 1);
  EXPECT_THROW(net.solve(1.0), std::invalid_argument);  // electrodes not set
  net.set_electrodes(H, L);
  EXPECT_THROW(net.solve(0.0), std::invalid_argument);
  EXPECT_THROW(net.solve(std::nan("")), std::invalid_argument);
  EXPECT_THROW(net.solve(kInf), std::invalid_argument);
  EXPECT_NO_THROW(net.solve(1.0));
}

TEST(EdgeCases, ChangesAfterSolveInvalidateResults)
{
  ConductionNetwork net;
  net.set_electrodes(H, L);
  net.add_conductance(H, L, 1);
  net.solve(1.0);
  EXPECT_EQ(net.potential(H), 1.0);
  net.add_conductance(H, 7, 1);
  EXPECT_EQ(net.potential(H), 0.0);  // stale results are not reported
  for (const NetworkEdge &e : net.edges()) EXPECT_EQ(e.current, 0.0);
  EXPECT_EQ(net.solve(1.0).resistance, 1.0);
}

TEST(EdgeCases, ExtremeConductancesStayFinite)
{
  // Series: R = 1/1e-300 + 1/1e300 = 1e300 (a product g1 g2 would overflow to inf and give
  // NaN); parallel with it: R = 1/(1e300 + 1e-300) = 1e-300.
  ConductionNetwork chain;
  chain.set_electrodes(H, L);
  chain.add_conductance(H, 10, 1e-300);
  chain.add_conductance(10, L, 1e300);
  const NetworkSolution s = chain.solve(1.0);
  EXPECT_EQ(s.method, SolveMethod::ClosedForm);
  EXPECT_DOUBLE_EQ(s.resistance, 1e300);
  chain.add_conductance(H, L, 1e300);
  EXPECT_DOUBLE_EQ(chain.solve(1.0).resistance, 1e-300);
  // A bridge over 200 decades needs a solve (no node of degree 2).
  for (auto kind : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
    ConductionNetwork net;
    net.set_electrodes(H, L);
    net.add_conductance(H, 10, 1e100);
    net.add_conductance(H, 11, 1e-100);
    net.add_conductance(10, L, 1e-100);
    net.add_conductance(11, L, 1e100);
    net.add_conductance(10, 11, 1.0);
    const NetworkSolution s = net.solve(1.0, kind);
    const double r = s.resistance;
    EXPECT_TRUE(std::isfinite(r));
    // LDL^T meets a zero pivot (and CG a singular scaled matrix): the exact elimination.
    EXPECT_EQ(s.method, SolveMethod::Elimination);
    // Exact: the two 1e100 edges and the bridge form the only good path, R ~ 1 + 2e-100.
    EXPECT_NEAR(r, 1.0, 1e-12);
  }
}
