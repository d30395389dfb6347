// SPDX-License-Identifier: GPL-2.0-or-later
// CG preconditioned by algebraic multigrid (src_fix/lib/network/multigrid_cg.*, hypre's BoomerAMG)
// and its use by the network solver. References: a dense long-double solve (test utils), the sparse
// direct solve, ngspice, and the analytic solution of a 1D Laplacian. A separate executable:
// hypre brings MPI up, which the leak-checked (ASan) run of test_network must not see.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "network/conduction_network.h"
#include "network/multigrid_cg.h"
#include "network_test_utils.h"

using namespace ohmdem;
using namespace ohmdem_test;

namespace {

SolverOptions amg()
{
  SolverOptions o;
  o.kind = SolverKind::ConjugateGradient;
  o.preconditioner = Preconditioner::Multigrid;
  return o;
}

}  // namespace

TEST(Multigrid, OneDimensionalLaplacianAgainstItsExactSolution)
{
  // -u'' = 1 on n interior points with u = 0 at both ends: tridiagonal (2, -1), whose exact
  // discrete solution is u_i = i (n + 1 - i) / 2 (second differences of a quadratic are exact).
  const int n = 2000;
  std::vector<int> start{0}, cols;
  std::vector<double> vals, b(n, 1.0), x(n, 0.0);
  for (int i = 0; i < n; ++i) {
    if (i > 0) cols.push_back(i - 1), vals.push_back(-1.0);
    cols.push_back(i), vals.push_back(2.0);
    if (i + 1 < n) cols.push_back(i + 1), vals.push_back(-1.0);
    start.push_back(static_cast<int>(cols.size()));
  }
  const MultigridResult r =
      multigrid_cg(n, start.data(), cols.data(), vals.data(), b.data(), x.data(), 1e-12, 200);
  ASSERT_TRUE(r.converged);
  EXPECT_LT(r.iterations, 30);  // CG alone needs ~n/2 = 1000 here
  EXPECT_LE(r.relative_residual, 1e-12);
  double err = 0.0;
  for (int i = 0; i < n; ++i) {
    const double exact = 0.5 * (i + 1.0) * (n - i);
    err = std::max(err, std::fabs(x[i] - exact) / exact);
  }
  EXPECT_LT(err, 1e-8);
  // Starting from the answer, nothing is left to do.
  const MultigridResult again =
      multigrid_cg(n, start.data(), cols.data(), vals.data(), b.data(), x.data(), 1e-10, 200);
  EXPECT_LE(again.iterations, 1);
  // An empty system is solved.
  EXPECT_TRUE(
      multigrid_cg(0, start.data(), nullptr, nullptr, nullptr, nullptr, 1e-8, 10).converged);
}

TEST(Multigrid, MatchesTheDenseReference)
{
  for (const DenseCase &c : kDenseCases) {
    const RandomNetwork rn = random_network(c.nodes, c.extra, c.lg_min, c.lg_max, 7);
    const double ref = double(dense_resistance(rn));
    const NetworkSolution s = solve_with(rn, amg());
    EXPECT_EQ(s.method, SolveMethod::MultigridCG) << c.lg_min;
    EXPECT_GT(s.iterations, 0);
    EXPECT_NEAR(s.resistance, ref, 1e-12 * ref) << c.lg_min;
  }
  const RandomNetwork p3 = packing_network(6, 6, 6, 3);
  const double ref = double(dense_resistance(p3));
  EXPECT_NEAR(solve_with(p3, amg()).resistance, ref, 1e-12 * ref);
}

TEST(Multigrid, IterationsHardlyGrowWithSizeUnlikeDiagonalCG)
{
  // 3D packings from ~900 to ~30000 unknowns (33x): diagonal CG's iterations grow with the
  // packing's diameter (55 -> 179 measured), multigrid's stay nearly flat (11 -> 18).
  SolverOptions jacobi = kind(SolverKind::ConjugateGradient);
  int amg_small = 0, amg_large = 0, jac_small = 0, jac_large = 0;
  for (int n : {7, 22}) {
    const RandomNetwork rn = packing_network(n, n, n, 1);
    const NetworkSolution d = solve_with(rn, kind(SolverKind::Direct));
    const NetworkSolution a = solve_with(rn, amg());
    const NetworkSolution j = solve_with(rn, jacobi);
    EXPECT_NEAR(a.resistance, d.resistance, 1e-12 * d.resistance) << n;
    (n == 7 ? amg_small : amg_large) = a.iterations;
    (n == 7 ? jac_small : jac_large) = j.iterations;
  }
  std::printf("[ info ] iterations 7^3 -> 22^3: multigrid %d -> %d, diagonal %d -> %d\n", amg_small,
              amg_large, jac_small, jac_large);
  EXPECT_LT(amg_large, 2 * amg_small);
  EXPECT_GT(jac_large, 2 * jac_small);
  EXPECT_LT(4 * amg_large, jac_large);
}

TEST(Multigrid, TwelveDecadesOfConductance)
{
  // Same case as Solvers.TwelveDecadesToNearMachinePrecision: diagonal CG needs ~1500
  // iterations, multigrid a small fraction of them, to the same accuracy.
  const RandomNetwork rn = widened(packing_network(14, 14, 1, 6), 12, 9);
  const double ref = double(dense_resistance(rn));
  const NetworkSolution s = solve_with(rn, amg());
  EXPECT_EQ(s.method, SolveMethod::MultigridCG);
  EXPECT_LT(s.iterations, 300);
  EXPECT_NEAR(s.resistance, ref, 1e-13 * ref);
}

TEST(Multigrid, WarmStartAndBitwiseRepeatable)
{
  const RandomNetwork rn = packing_network(30, 30, 1, 21);
  const RandomNetwork next = perturbed(rn, 0.01, 4);
  const double ref = solve_with(next, kind(SolverKind::Direct)).resistance;
  ConductionNetwork net;
  net.set_options(amg());
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  add_all(net, rn.edges);
  net.solve(0.1);
  net.clear();
  add_all(net, next.edges);
  const NetworkSolution warm = net.solve(0.1);
  net.reset();
  add_all(net, next.edges);
  const NetworkSolution cold = net.solve(0.1);
  EXPECT_NEAR(warm.resistance, ref, 1e-12 * ref);
  EXPECT_NEAR(cold.resistance, ref, 1e-12 * ref);
  EXPECT_LT(warm.iterations, cold.iterations);
  // The same deck twice gives the same numbers.
  EXPECT_EQ(solve_with(next, amg()).resistance, cold.resistance);
}

TEST(Multigrid, AutoUsesItForLargeCGSystemsOnly)
{
  const RandomNetwork rn = packing_network(10, 10, 10, 2);  // ~3000 unknowns, 3D: CG
  SolverOptions o;
  EXPECT_EQ(solve_with(rn, o).method, SolveMethod::ConjugateGradient);
  o.auto_multigrid_unknowns = 1000;
  EXPECT_EQ(solve_with(rn, o).method, SolveMethod::MultigridCG);
  // Direct stays direct whatever the size threshold.
  const RandomNetwork small = random_network(300, 600, -1, 1, 2);
  EXPECT_EQ(solve_with(small, o).method, SolveMethod::Direct);
}

TEST(Multigrid, FallsBackToDirectWhenItCannotConverge)
{
  const RandomNetwork rn = random_network(300, 600, -6, 6, 2);
  SolverOptions o = amg();
  o.cg_max_iterations = 1;
  o.cg_tolerance = 1e-14;
  const NetworkSolution s = solve_with(rn, o);
  const double ref = double(dense_resistance(rn));
  EXPECT_EQ(s.method, SolveMethod::Direct);
  EXPECT_NEAR(s.resistance, ref, 1e-12 * ref);
}

TEST(Multigrid, AgreesWithNgspice)
{
  if (!have_ngspice()) GTEST_SKIP() << "ngspice not installed";
  const RandomNetwork rn = widened(packing_network(12, 12, 1, 5), 12, 3);
  ConductionNetwork net;
  net.set_options(amg());
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  add_all(net, rn.edges);
  const NetworkSolution s = net.solve(0.1);
  ASSERT_EQ(s.method, SolveMethod::MultigridCG);
  std::string err;
  const double spice = ngspice_ehigh_voltage(net, 0.1, "multigrid_12_decades", err) / 0.1;
  ASSERT_TRUE(std::isfinite(spice)) << err;
  EXPECT_NEAR(s.resistance, spice, 1e-9 * spice);
}
