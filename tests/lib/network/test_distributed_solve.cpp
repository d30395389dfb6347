// SPDX-License-Identifier: GPL-2.0-or-later
// The distributed network solve (src_fix/lib/network/distributed_solve.*, distributed_system.*,
// key_directory.*), run by CTest under mpirun with 1, 2 and 3 processes. Every rank builds the
// same global test network and takes a scattered share of it (nodes and edges dealt out by a
// hash, unrelated to the graph), so the routing, numbering and component search are all
// exercised. References: closed forms (series-parallel, Wheatstone bridge), the dense
// long-double Kron elimination of the test utilities, and the serial sparse direct solve.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "network/conduction_network.h"
#include "network/distributed_solve.h"
#include "network_test_utils.h"

using namespace ohmdem;
using namespace ohmdem_test;

namespace {

int rank()
{
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int nprocs()
{
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}
std::uint64_t scramble(std::uint64_t z)
{
  z = (z ^ (z >> 33)) * 0xff51afd7ed558ccdull;
  return z ^ (z >> 29);
}

// This rank's share: the nodes (but the electrodes) and edges whose scrambled index falls here.
struct Share {
  std::vector<NodeKey> owned;
  std::vector<DistributedEdge> edges;
};
Share share_of(const RandomNetwork &net)
{
  Share s;
  const auto P = static_cast<std::uint64_t>(nprocs()), me = static_cast<std::uint64_t>(rank());
  for (std::size_t k = 2; k < net.keys.size(); ++k)
    if (scramble(net.keys[k] + 1) % P == me) s.owned.push_back(net.keys[k]);
  for (std::size_t e = 0; e < net.edges.size(); ++e)
    if (scramble(e * 7919 + 3) % P == me)
      s.edges.push_back({net.edges[e].a, net.edges[e].b, net.edges[e].g});
  return s;
}

DistributedSolution solve(DistributedNetworkSolver &solver, const RandomNetwork &net,
                          double current = 0.1)
{
  const Share s = share_of(net);
  return solver.solve(s.owned, s.edges, net.keys[0], net.keys[1], current);
}

std::uint64_t bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

}  // namespace

TEST(Distributed, SeriesParallelAndBridgeAgainstClosedForms)
{
  // Three chains of 1..3 ohm resistors in parallel between H and L: R = 1 / (1/6 + 1/6 + 1/6)
  // per chain 1+2+3 = 6 ohm, so 2 ohm. Then the Wheatstone bridge (1, 2, 3, 5, 7 ohm) of
  // test_conduction_network_closed_form.cpp: 257/101 ohm.
  RandomNetwork chains;
  const NodeKey H = 1, L = 2;
  chains.keys = {H, L};
  for (NodeKey c = 0; c < 3; ++c) {
    const NodeKey a = 100 + 10 * c, b = a + 1;
    chains.keys.insert(chains.keys.end(), {a, b});
    chains.edges.push_back({H, a, 1.0});
    chains.edges.push_back({a, b, 0.5});
    chains.edges.push_back({b, L, 1.0 / 3.0});
  }
  DistributedNetworkSolver solver(MPI_COMM_WORLD);
  const DistributedSolution r = solve(solver, chains);
  EXPECT_TRUE(r.connected);
  EXPECT_EQ(r.unknowns, 6);
  EXPECT_NEAR(r.resistance, 2.0, 2e-12);

  RandomNetwork bridge;
  const NodeKey A = 11, B = 12;
  bridge.keys = {H, L, A, B};
  bridge.edges = {{H, A, 1.0}, {H, B, 0.5}, {A, L, 1.0 / 3}, {B, L, 0.2}, {A, B, 1.0 / 7}};
  DistributedNetworkSolver s2(MPI_COMM_WORLD);
  EXPECT_NEAR(solve(s2, bridge, 1.0).resistance, 257.0 / 101.0, 1e-12);
  // Potentials at I = 1 A (V_A, V_B from the bridge's node equations, numpy.linalg.solve on
  // [[1+1/3+1/7, -1/7], [-1/7, 0.5+0.2+1/7]] [VA VB] = [V_H, 0.5 V_H] with V_H = 257/101).
  const std::vector<double> v = s2.potentials({H, L, A, B});
  EXPECT_NEAR(v[0], 257.0 / 101.0, 1e-12);
  EXPECT_EQ(v[1], 0.0);
  const double vh = 257.0 / 101.0, d = (1 + 1.0 / 3 + 1.0 / 7) * (0.7 + 1.0 / 7) - 1.0 / 49;
  EXPECT_NEAR(v[2], (vh * (0.7 + 1.0 / 7) + 0.5 * vh / 7) / d, 1e-11);
  EXPECT_NEAR(v[3], ((1 + 1.0 / 3 + 1.0 / 7) * 0.5 * vh + vh / 7) / d, 1e-11);
}

TEST(Distributed, PackingAgainstDenseAndSerialSolves)
{
  // 3D packing-like network (3380 contact nodes) and a random graph with conductances over
  // 12 decades: R within 1e-10 of the long-double Kron elimination and of the serial solve.
  for (const RandomNetwork &net :
       {packing_network(8, 8, 6, 11), widened(random_network(600, 1200, -1, 1, 5), 12, 9)}) {
    const double ref = static_cast<double>(dense_kron_resistance(net));
    const double serial = solve_with(net, kind(SolverKind::Direct)).resistance;
    DistributedNetworkSolver solver(MPI_COMM_WORLD);
    const DistributedSolution r = solve(solver, net);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.resistance / ref, 1.0, 1e-10) << "unknowns " << r.unknowns;
    EXPECT_NEAR(r.resistance / serial, 1.0, 1e-10);
    EXPECT_EQ(r.floating_nodes, 0);
    EXPECT_EQ(r.edges, static_cast<long long>(net.edges.size()));
  }
}

TEST(Distributed, BitwiseRepeatableForAFixedProcessCount)
{
  const RandomNetwork net = packing_network(7, 7, 5, 3);
  DistributedNetworkSolver a(MPI_COMM_WORLD), b(MPI_COMM_WORLD);
  const double ra = solve(a, net).resistance, rb = solve(b, net).resistance;
  EXPECT_EQ(bits(ra), bits(rb));
  const Share s = share_of(net);
  for (NodeKey k : s.owned) ASSERT_EQ(bits(a.potential(k)), bits(b.potential(k)));
}

TEST(Distributed, KeepsTheMultigridSetupWhileConductancesChangeLittle)
{
  const RandomNetwork net = packing_network(8, 8, 5, 21);
  DistributedNetworkSolver solver(MPI_COMM_WORLD);
  const DistributedSolution first = solve(solver, net);
  EXPECT_FALSE(first.setup_reused);
  EXPECT_EQ(first.setups, 1);
  // 1 % changes: the hierarchy is kept, R still within 1e-10 of the dense reference.
  const RandomNetwork step = perturbed(net, 0.01, 4);
  const DistributedSolution kept = solve(solver, step);
  EXPECT_TRUE(kept.setup_reused);
  EXPECT_EQ(kept.setups, 1);
  EXPECT_NEAR(kept.resistance / static_cast<double>(dense_kron_resistance(step)), 1.0, 1e-10);
  // 50 % changes exceed the default tolerance (10 %): a new setup.
  const RandomNetwork jump = perturbed(net, 0.5, 5);
  const DistributedSolution fresh = solve(solver, jump);
  EXPECT_FALSE(fresh.setup_reused);
  EXPECT_EQ(fresh.setups, 2);
  EXPECT_NEAR(fresh.resistance / static_cast<double>(dense_kron_resistance(jump)), 1.0, 1e-10);
  // A new edge changes the pattern: a new setup.
  RandomNetwork grown = jump;
  grown.edges.push_back({grown.keys[5], grown.keys[40], 0.3});
  const DistributedSolution regrown = solve(solver, grown);
  EXPECT_FALSE(regrown.setup_reused);
  EXPECT_NEAR(regrown.resistance / static_cast<double>(dense_kron_resistance(grown)), 1.0, 1e-10);
}

TEST(Distributed, StopsWhenRIsAccurateNotWhenTheResidualIsTiny)
{
  // CG stops on its estimate of the error of the power (hence of R), not on a 1e-12 residual:
  // fewer iterations, R within 1e-10 of the dense long-double reference. The power at any
  // iterate is above the true one, so R is approached from below. With the estimate off
  // (energy_tolerance 0) CG runs to the residual test; with a loose one (1e-6) R is off by
  // about that much and no more.
  const RandomNetwork net = packing_network(8, 8, 6, 11);
  const double ref = static_cast<double>(dense_kron_resistance(net));
  auto with = [&](double energy_tolerance) {
    DistributedNetworkSolver solver(MPI_COMM_WORLD);
    DistributedOptions o;
    o.energy_tolerance = energy_tolerance;
    solver.set_options(o);
    return solve(solver, net);
  };
  const DistributedSolution standard = with(DistributedOptions().energy_tolerance);
  const DistributedSolution residual = with(0.0);
  const DistributedSolution loose = with(1e-6);
  EXPECT_LT(standard.iterations, residual.iterations);
  EXPECT_LT(loose.iterations, standard.iterations);
  EXPECT_NEAR(standard.resistance / ref, 1.0, 1e-10);
  EXPECT_NEAR(residual.resistance / ref, 1.0, 1e-12);
  EXPECT_LT(loose.resistance, ref);
  EXPECT_GT(loose.resistance / ref, 1.0 - 1e-5);
  EXPECT_LE(standard.resistance, ref * (1.0 + 1e-13));
}

TEST(Distributed, FloatingComponentsAreDroppedAndAnOpenNetworkIsInfinite)
{
  // The bridge plus a ring touching no electrode (floating: singular if kept) and a dead
  // branch on H (at V_H): R unchanged, the ring's 3 nodes dropped.
  const NodeKey H = 1, L = 2, A = 11, B = 12, X = 21, Y = 22, Z = 23, D = 31;
  RandomNetwork net;
  net.keys = {H, L, A, B, X, Y, Z, D};
  net.edges = {{H, A, 1.0}, {H, B, 0.5}, {A, L, 1.0 / 3}, {B, L, 0.2}, {A, B, 1.0 / 7},
               {X, Y, 2.0}, {Y, Z, 3.0}, {Z, X, 4.0},     {H, D, 5.0}};
  DistributedNetworkSolver solver(MPI_COMM_WORLD);
  const DistributedSolution r = solve(solver, net, 1.0);
  EXPECT_NEAR(r.resistance, 257.0 / 101.0, 1e-12);
  EXPECT_EQ(r.floating_nodes, 3);
  const std::vector<double> v = solver.potentials({X, D});
  EXPECT_EQ(v[0], 0.0);
  EXPECT_NEAR(v[1], 257.0 / 101.0, 1e-12);

  // Cut both paths to L: no path, R = inf, every potential finite.
  RandomNetwork open = net;
  open.edges.erase(open.edges.begin() + 2, open.edges.begin() + 4);
  const DistributedSolution o = solve(solver, open, 1.0);
  EXPECT_FALSE(o.connected);
  EXPECT_EQ(o.resistance, std::numeric_limits<double>::infinity());
  for (double x : solver.potentials({H, A, B, X, D})) EXPECT_TRUE(std::isfinite(x));
  // Only the electrodes joined directly: R = 1/g.
  RandomNetwork direct;
  direct.keys = {H, L};
  direct.edges = {{H, L, 4.0}};
  EXPECT_DOUBLE_EQ(solve(solver, direct).resistance, 0.25);
}

TEST(Distributed, AnEdgeToANodeNobodyOwnsIsACallerBug)
{
  DistributedNetworkSolver solver(MPI_COMM_WORLD);
  std::vector<NodeKey> owned;
  if (rank() == 0) owned = {10};
  std::vector<DistributedEdge> edges;
  if (rank() == 0) edges = {{1, 10, 1.0}, {10, 99, 1.0}, {99, 2, 1.0}};
  EXPECT_THROW(solver.solve(owned, edges, 1, 2, 0.1), std::invalid_argument);
  EXPECT_THROW(solver.solve(owned, {}, 1, 2, 0.0), std::invalid_argument);
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (rank() != 0) {  // one report; a failure on any rank still fails the run (exit code)
    auto &listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS();
  int any = failed;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any;
}
