// SPDX-License-Identifier: GPL-2.0-or-later
// Sparse solvers against an independent dense long-double solve; direct vs CG; warm start;
// exact reduction; Kirchhoff's current law; bitwise determinism under shuffled insertion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "network/conduction_network.h"
#include "network/network_export.h"
#include "network_test_utils.h"

using namespace ohmdem;
using namespace ohmdem_test;

TEST(Solvers, DirectAndCGMatchDenseReference)
{
  // Reference: dense long-double full-pivot LU of the same Laplacian (test utils).
  for (const DenseCase &c : kDenseCases) {
    const RandomNetwork rn = random_network(c.nodes, c.extra, c.lg_min, c.lg_max, 7);
    const double ref = double(dense_resistance(rn));
    const NetworkSolution d = solve_with(rn, kind(SolverKind::Direct));
    const NetworkSolution g = solve_with(rn, kind(SolverKind::ConjugateGradient));
    SolverOptions jac = kind(SolverKind::ConjugateGradient);
    jac.preconditioner = Preconditioner::Diagonal;
    const NetworkSolution j = solve_with(rn, jac);
    EXPECT_EQ(d.method, SolveMethod::Direct);
    EXPECT_EQ(g.method, SolveMethod::ConjugateGradient);
    EXPECT_EQ(j.method, SolveMethod::ConjugateGradient);
    EXPECT_GT(d.unknowns, 100);
    // Measured: ~1e-16..1e-15 for all three (R from the energy functional, summed by edge).
    EXPECT_NEAR(d.resistance, ref, 1e-14 * ref) << c.lg_min;
    EXPECT_NEAR(g.resistance, ref, 1e-12 * ref) << c.lg_min;
    EXPECT_NEAR(j.resistance, ref, 1e-12 * ref) << c.lg_min;
    EXPECT_LT(d.relative_residual, 1e-10);
    EXPECT_GT(g.iterations, 0);
  }
}

TEST(Solvers, PackingNetwork3D)
{
  const RandomNetwork rn = packing_network(6, 6, 6, 3);
  const double ref = double(dense_resistance(rn));
  const NetworkSolution d = solve_with(rn, kind(SolverKind::Direct));
  const NetworkSolution g = solve_with(rn, kind(SolverKind::ConjugateGradient));
  EXPECT_NEAR(d.resistance, ref, 1e-14 * ref);
  EXPECT_NEAR(g.resistance, ref, 1e-12 * ref);
  EXPECT_GT(d.unknowns, 400);
}

TEST(Solvers, TwelveDecadesToNearMachinePrecision)
{
  // A 2D packing with every g multiplied by 10^U(-6, 6). R is well conditioned (monotone in
  // every g, scales as 1/g), but a plain double LDL^T loses ~3 digits here (5e-12 measured
  // before the edge-wise refinement); the dense long-double LU is within 1.2e-15 of the exact
  // rational result (tests/lib/network/kron_exact.py on the exported netlist).
  const RandomNetwork rn = widened(packing_network(14, 14, 1, 6), 12, 9);
  const double ref = double(dense_resistance(rn));
  SolverOptions cg = kind(SolverKind::ConjugateGradient);
  cg.cg_max_iterations = 100000;  // ~1500 needed: do not fall back to the direct solve
  const NetworkSolution d = solve_with(rn, kind(SolverKind::Direct));
  const NetworkSolution g = solve_with(rn, cg);
  EXPECT_EQ(g.method, SolveMethod::ConjugateGradient);
  EXPECT_GT(g.iterations, 1000);
  EXPECT_NEAR(d.resistance, ref, 1e-14 * ref);
  EXPECT_NEAR(g.resistance, ref, 1e-13 * ref);
}

TEST(Solvers, BeyondSixteenDecadesTheExactEliminationTakesOver)
{
  // Conductances spread over 20 and 30 decades make the assembled matrix numerically
  // singular for LDL^T: the refinement cannot converge and the subtraction-free Kron
  // elimination takes over. Reference: dense long-double Kron elimination (test utils);
  // kron_exact.py on the exported netlists agrees with our R to 2e-16 for both.
  for (double decades : {20.0, 30.0}) {
    const RandomNetwork rn = widened(packing_network(10, 10, 1, 6), decades, 9);
    const double ref = double(dense_kron_resistance(rn));
    const NetworkSolution d = solve_with(rn, kind(SolverKind::Direct));
    EXPECT_EQ(d.method, SolveMethod::Elimination) << decades;
    EXPECT_NEAR(d.resistance, ref, 1e-14 * ref) << decades;
  }
  // CG on 20 decades still converges (~3900 iterations) and agrees to ~1e-14.
  const RandomNetwork rn = widened(packing_network(10, 10, 1, 6), 20, 9);
  SolverOptions cg = kind(SolverKind::ConjugateGradient);
  cg.cg_max_iterations = 100000;
  const NetworkSolution g = solve_with(rn, cg);
  EXPECT_EQ(g.method, SolveMethod::ConjugateGradient);
  const double ref = double(dense_kron_resistance(rn));
  EXPECT_NEAR(g.resistance, ref, 1e-12 * ref);
}

TEST(Solvers, ReductionIsExact)
{
  // Sparse random graph: many dangling and degree-2 nodes. Same R with and without the
  // reduction, and the same potentials on every node (recovered by back-substitution).
  const RandomNetwork rn = random_network(500, 100, -2, 2, 11);
  ConductionNetwork a, b;
  SolverOptions o = kind(SolverKind::Direct);
  a.set_options(o);
  o.reduce_series = false;
  b.set_options(o);
  for (ConductionNetwork *n : {&a, &b}) {
    n->set_electrodes(rn.keys[0], rn.keys[1]);
    add_all(*n, rn.edges);
  }
  const NetworkSolution sa = a.solve(1.0), sb = b.solve(1.0);
  EXPECT_GT(sa.eliminated_nodes, 200);
  EXPECT_LT(sa.unknowns, sb.unknowns);
  EXPECT_NEAR(sa.resistance, sb.resistance, 1e-12 * sb.resistance);
  for (NodeKey k : rn.keys) EXPECT_NEAR(a.potential(k), b.potential(k), 1e-12 * sb.resistance);
}

TEST(Solvers, KirchhoffCurrentLaw)
{
  // Net current out of every internal node is zero; I leaves H and enters L.
  const RandomNetwork rn = random_network(300, 600, -4, 4, 5);
  for (auto k : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
    ConductionNetwork net;
    net.set_options(kind(k));
    net.set_electrodes(rn.keys[0], rn.keys[1]);
    add_all(net, rn.edges);
    const double I = 0.1;
    net.solve(I);
    // Rounding scale of a node's balance: sum of g (|V_a| + |V_b|) over its edges (a current
    // g (V_a - V_b) through a large g cancels digits of the potentials).
    std::map<NodeKey, double> out, scale;
    for (const NetworkEdge &e : net.edges()) {
      const double s =
          e.conductance * (std::fabs(net.potential(e.a)) + std::fabs(net.potential(e.b)));
      out[e.a] += e.current;
      out[e.b] -= e.current;
      scale[e.a] += s;
      scale[e.b] += s;
    }
    const double tol = k == SolverKind::Direct ? 1e-12 : 1e-8;
    EXPECT_NEAR(out[rn.keys[0]], I, tol * scale[rn.keys[0]]);
    EXPECT_NEAR(out[rn.keys[1]], -I, tol * scale[rn.keys[1]]);
    for (const auto &[key, net_out] : out)
      if (key != rn.keys[0] && key != rn.keys[1]) {
        EXPECT_NEAR(net_out, 0.0, tol * scale[key]);
      }
  }
}

TEST(Solvers, WarmStartReducesIterations)
{
  // Two "time steps": every conductance changes by up to +-1 % (contacts evolve slowly).
  // The second CG solve starts from the first one's potentials.
  const RandomNetwork rn = packing_network(30, 30, 1, 21);
  const RandomNetwork next = perturbed(rn, 0.01, 4);
  // Reference: the direct solver (checked against the dense solve in the tests above).
  const double ref = solve_with(next, kind(SolverKind::Direct)).resistance;

  ConductionNetwork net;
  net.set_options(kind(SolverKind::ConjugateGradient));
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  add_all(net, rn.edges);
  const NetworkSolution first = net.solve(0.1);
  net.clear();  // keeps the warm-start potentials
  add_all(net, next.edges);
  const NetworkSolution warm = net.solve(0.1);
  net.reset();  // forgets them
  add_all(net, next.edges);
  const NetworkSolution cold = net.solve(0.1);
  EXPECT_NEAR(warm.resistance, ref, 1e-9 * ref);
  EXPECT_NEAR(cold.resistance, ref, 1e-9 * ref);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_GT(first.iterations, 0);
  // Same network, doubled current: the stored potentials are per unit current, so the
  // guess is already the answer.
  const NetworkSolution again = net.solve(0.2);
  EXPECT_LE(again.iterations, 1);
  EXPECT_NEAR(again.resistance, ref, 1e-9 * ref);
  std::printf("[ info ] CG iterations: cold %d, warm (1%% change) %d, same network %d\n",
              cold.iterations, warm.iterations, again.iterations);
}

TEST(Solvers, AutoChoice)
{
  // Default rule: small systems direct; mid-size ones by predicted factorization cost,
  // which is low for 2D packings (direct) and high for 3D ones (CG).
  const RandomNetwork rn = random_network(300, 600, -1, 1, 2);
  SolverOptions o;
  EXPECT_EQ(solve_with(rn, o).method, SolveMethod::Direct);
  o.auto_direct_unknowns = 0;
  o.auto_cg_unknowns = 10;
  EXPECT_EQ(solve_with(rn, o).method, SolveMethod::ConjugateGradient);
  const SolverOptions def;
  const NetworkSolution p2 = solve_with(packing_network(40, 40, 1, 2), def);
  EXPECT_GT(p2.unknowns, def.auto_direct_unknowns);
  EXPECT_EQ(p2.method, SolveMethod::Direct);
  const NetworkSolution p3 = solve_with(packing_network(10, 10, 10, 2), def);
  EXPECT_GT(p3.unknowns, def.auto_direct_unknowns);
  EXPECT_EQ(p3.method, SolveMethod::ConjugateGradient);
}

TEST(Solvers, CGFallsBackToDirectWhenItCannotConverge)
{
  const RandomNetwork rn = random_network(300, 600, -6, 6, 2);
  SolverOptions o = kind(SolverKind::ConjugateGradient);
  o.preconditioner = Preconditioner::Diagonal;
  o.cg_max_iterations = 2;
  const NetworkSolution s = solve_with(rn, o);
  const double ref = double(dense_resistance(rn));
  EXPECT_EQ(s.method, SolveMethod::Direct);
  EXPECT_NEAR(s.resistance, ref, 1e-12 * ref);
}

TEST(Solvers, FactorizationReusedWhenPatternUnchanged)
{
  // Same topology, new values (the direct solver reuses its symbolic analysis): still right.
  RandomNetwork rn = random_network(200, 400, -2, 2, 8);
  ConductionNetwork net;
  net.set_options(kind(SolverKind::Direct));
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  for (int step = 0; step < 3; ++step) {
    for (Edge &e : rn.edges) e.g *= 1.0 + 0.3 * step;
    net.clear();
    add_all(net, rn.edges);
    const double ref = double(dense_resistance(rn));
    EXPECT_NEAR(net.solve(1.0).resistance, ref, 1e-12 * ref);
  }
}

TEST(Solvers, ShuffledInsertionIsBitwiseIdentical)
{
  // Same edges in another order and orientation (as gathered from MPI ranks in rank order):
  // R, potentials, iterations, netlist and VTK must be identical, not just close.
  const RandomNetwork rn = random_network(300, 600, -6, 6, 99);
  RandomNetwork bearing;
  bearing.keys = {1, 2};
  for (int k = 0; k < 13; ++k) bearing.edges.push_back({1, 2, 0.1 + 0.01 * k});
  for (const RandomNetwork *base : {&rn, static_cast<const RandomNetwork *>(&bearing)})
    for (auto k : {SolverKind::Direct, SolverKind::ConjugateGradient}) {
      std::string ref_netlist, ref_vtk;
      NetworkSolution ref;
      std::vector<double> ref_v;
      std::mt19937_64 rng(1);
      for (int trial = 0; trial < 4; ++trial) {
        std::vector<Edge> edges = base->edges;
        std::shuffle(edges.begin(), edges.end(), rng);
        for (Edge &e : edges)
          if (rng() % 2) std::swap(e.a, e.b);
        ConductionNetwork net;
        net.set_options(kind(k));
        net.set_electrodes(base->keys[0], base->keys[1]);
        add_all(net, edges);
        const NetworkSolution s = net.solve(0.1);
        std::ostringstream nl, vtk;
        write_spice_netlist(nl, net, 0.1);
        write_vtk_network(vtk, net, [](NodeKey key, std::array<double, 3> &p) {
          p = {double(key % 1000), double(key % 7), 0.0};
          return true;
        });
        std::vector<double> v;
        for (NodeKey key : base->keys) v.push_back(net.potential(key));
        if (trial == 0) {
          ref = s;
          ref_netlist = nl.str();
          ref_vtk = vtk.str();
          ref_v = v;
          continue;
        }
        EXPECT_EQ(s.resistance, ref.resistance);  // bitwise
        EXPECT_EQ(s.iterations, ref.iterations);
        EXPECT_EQ(s.relative_residual, ref.relative_residual);
        EXPECT_EQ(v, ref_v);
        EXPECT_EQ(nl.str(), ref_netlist);
        EXPECT_EQ(vtk.str(), ref_vtk);
      }
    }
}
