// SPDX-License-Identifier: GPL-2.0-or-later
// Speed versus accuracy of the network solvers on packing-like networks (2D and 3D lattices
// of particles, one node per contact, eq. 1 cliques inside each particle): sparse direct
// (LDL^T) against preconditioned CG, cold and warm-started, from 1e3 to 1e5 nodes, plus the
// closed form of the bearing. Times are per step (rebuild from the edge list + solve), the
// minimum of a few repetitions; errors are relative to the direct solve.
// Run: bench_network_solve [max_nodes (default 1e5)]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "network/conduction_network.h"
#include "network_test_utils.h"

using namespace ohmdem;
using namespace ohmdem_test;

namespace {

using Clock = std::chrono::steady_clock;

const char *name(Preconditioner pc)
{
  switch (pc) {
    case Preconditioner::Diagonal: return "CG-Jacobi";
    case Preconditioner::IncompleteCholesky: return "CG-IC";
    case Preconditioner::Multigrid: return "CG-AMG";
  }
  return "?";
}

struct Timed {
  NetworkSolution s;
  double ms;
};

double ms_since(Clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// One "time step" as the compute does it: clear, add every edge, solve.
Timed step(ConductionNetwork &net, const RandomNetwork &rn, double current)
{
  const auto t0 = Clock::now();
  net.clear();
  add_all(net, rn.edges);
  NetworkSolution s = net.solve(current);
  return {s, ms_since(t0)};
}

ConductionNetwork make(const RandomNetwork &rn, SolverOptions o)
{
  ConductionNetwork net;
  net.set_options(o);
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  return net;
}

// Cold CG time per step (ms) and unknowns of each size, per preconditioner: for the growth.
struct Growth {
  std::vector<double> unknowns, jacobi_ms, amg_ms, jacobi_it, amg_it;
};

void run(const std::string &label, const RandomNetwork &rn, int reps, Growth *growth = nullptr,
         bool with_direct = true)
{
  const double I = 0.1;
  const RandomNetwork next = perturbed(rn, 1e-2, 7);   // next step, +-1 % on every g
  const RandomNetwork close = perturbed(rn, 1e-4, 8);  // next step, +-0.01 %
  SolverOptions o;
  double first = 1e300, same = 1e300;
  Timed d{};
  if (with_direct) {
    o.kind = SolverKind::Direct;
    ConductionNetwork direct = make(rn, o);
    for (int r = 0; r < reps; ++r) {
      direct.reset();
      first = std::min(first, step(direct, rn, I).ms);  // analyse + factorize
      d = step(direct, next, I);                        // same pattern: factorize only
      same = std::min(same, d.ms);
    }
  } else {
    // Too large to factorize (3D fill-in: minutes, gigabytes): the reference is CG run to
    // tol 1e-13, and the "direct/CG" ratio below is meaningless (printed as 0).
    o.kind = SolverKind::ConjugateGradient;
    o.cg_tolerance = 1e-13;
    ConductionNetwork tight = make(rn, o);
    d = step(tight, next, I);
    first = same = 0.0;
  }
  const double ref = d.s.resistance;
  std::printf("%-12s nodes %6zu edges %7zu unknowns %6d | direct %8.2f ms, same pattern %8.2f ms%s\n",
              label.c_str(), rn.keys.size(), rn.edges.size(), d.s.unknowns, first, same,
              with_direct ? "" : " (skipped, reference: CG to 1e-13)");
  o = SolverOptions{};
  {
    // The default Auto choice, cold, on a new pattern (its symbolic analysis included).
    double ms = 1e300;
    Timed t{};
    for (int r = 0; r < reps; ++r) {
      ConductionNetwork net = make(rn, SolverOptions{});
      t = step(net, next, I);
      ms = std::min(ms, t.ms);
    }
    std::printf("  auto -> %s: %8.2f ms cold, new pattern (err %.0e)\n", to_string(t.s.method), ms,
                std::max(1e-17, std::fabs(t.s.resistance - ref) / ref));
  }
  {
    // Fixed cost of a step (sort, components, reduction, assembly, scaling, residual): the
    // same network twice, the second CG solve starts from the exact answer (0 iterations).
    o.kind = SolverKind::ConjugateGradient;
    ConductionNetwork cg = make(rn, o);
    double ms = 1e300;
    for (int r = 0; r < reps; ++r) {
      step(cg, next, I);
      ms = std::min(ms, step(cg, next, I).ms);
    }
    std::printf("  fixed cost of a step (converged warm start, 0 CG iterations) %8.2f ms\n", ms);
  }
  for (Preconditioner pc : {Preconditioner::Diagonal, Preconditioner::IncompleteCholesky,
                            Preconditioner::Multigrid}) {
    o.kind = SolverKind::ConjugateGradient;
    o.preconditioner = pc;
    ConductionNetwork cg = make(rn, o);
    Timed cold{}, warm{}, warm2{};
    cold.ms = warm.ms = warm2.ms = 1e300;
    for (int r = 0; r < reps; ++r) {
      cg.reset();
      const Timed c = step(cg, next, I);
      step(cg, rn, I);
      const Timed w = step(cg, next, I);
      step(cg, rn, I);
      const Timed w2 = step(cg, close, I);
      if (c.ms < cold.ms) cold = c;
      if (w.ms < warm.ms) warm = w;
      if (w2.ms < warm2.ms) warm2 = w2;
    }
    std::printf(
        "  %-9s cold %8.2f ms %4d it | warm(1%%) %8.2f ms %4d it | warm(0.01%%) %8.2f ms "
        "%4d it | err %.0e | direct/CG %.2f\n",
        name(pc), cold.ms, cold.s.iterations, warm.ms,
        warm.s.iterations, warm2.ms, warm2.s.iterations,
        std::max(1e-17, std::fabs(cold.s.resistance - ref) / ref), same / cold.ms);
    if (growth && pc == Preconditioner::Diagonal) {
      growth->unknowns.push_back(cold.s.unknowns);
      growth->jacobi_ms.push_back(cold.ms);
      growth->jacobi_it.push_back(cold.s.iterations);
    } else if (growth && pc == Preconditioner::Multigrid) {
      growth->amg_ms.push_back(cold.ms);
      growth->amg_it.push_back(cold.s.iterations);
    }
  }
  std::fflush(stdout);
}

// Iterations, time and R error against the CG tolerance (cold start, Jacobi and IC).
void tolerance_sweep(const std::string &label, const RandomNetwork &rn)
{
  SolverOptions o;
  o.kind = SolverKind::Direct;
  ConductionNetwork direct = make(rn, o);
  const double ref = step(direct, rn, 0.1).s.resistance;
  std::printf("tolerance sweep, %s (cold CG): tol -> iterations, ms, |R - R_direct| / R\n",
              label.c_str());
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    std::printf("  tol %.0e", tol);
    for (Preconditioner pc : {Preconditioner::Diagonal, Preconditioner::IncompleteCholesky,
                              Preconditioner::Multigrid}) {
      o.kind = SolverKind::ConjugateGradient;
      o.preconditioner = pc;
      o.cg_tolerance = tol;
      ConductionNetwork cg = make(rn, o);
      const Timed t = step(cg, rn, 0.1);
      std::printf(" | %s %4d it %8.2f ms err %.1e",
                  name(pc) + 3, t.s.iterations, t.ms,
                  std::fabs(t.s.resistance - ref) / ref);
    }
    std::printf("\n");
  }
  std::fflush(stdout);
}

// The bearing: 13 two-contact balls, each one conductance between the races.
void bearing()
{
  ConductionNetwork net;
  net.set_electrodes(1, 2);
  const int n = 100000;
  const auto t0 = Clock::now();
  double sum = 0;
  for (int it = 0; it < n; ++it) {
    net.clear();
    for (int k = 0; k < 13; ++k) net.add_conductance(1, 2, 0.1 + 1e-3 * k + 1e-9 * it);
    sum += net.solve(0.1).resistance;
  }
  std::printf("bearing closed form (13 balls): %.2f us per step (checksum %.6g)\n",
              1e3 * ms_since(t0) / n, sum / n);
}

}  // namespace

int main(int argc, char **argv)
{
  const double max_nodes = argc > 1 ? std::atof(argv[1]) : 1e5;
  std::printf(
      "# bench_network_solve: per-step time (rebuild + solve, min of repetitions); "
      "err = |R - R_direct| / R_direct; CG tolerance %.0e\n",
      SolverOptions{}.cg_tolerance);
  bearing();
  for (int n : {16, 50, 160, 224}) {  // 2D: ~2 n^2 contact nodes
    if (2.0 * n * n > 1.3 * max_nodes) break;
    run("2D " + std::to_string(n) + "^2", packing_network(n, n, 1, 1), n < 100 ? 5 : 1);
  }
  Growth g3;
  for (int n : {7, 15, 22, 32, 46}) {  // 3D: ~3 n^3 contact nodes
    if (3.0 * n * n * n > 1.3 * max_nodes) break;
    run("3D " + std::to_string(n) + "^3", packing_network(n, n, n, 1), n < 20 ? 5 : 1, &g3,
        n < 40);
  }
  // Growth with size: t ~ N^p between the smallest and the largest 3D packing (p = 1 is
  // linear); the iteration counts show where it comes from.
  if (g3.unknowns.size() >= 2) {
    const std::size_t a = 0, b = g3.unknowns.size() - 1;
    auto power = [&](const std::vector<double> &t) {
      return std::log(t[b] / t[a]) / std::log(g3.unknowns[b] / g3.unknowns[a]);
    };
    std::printf("growth, 3D %.0f -> %.0f unknowns (cold): CG-Jacobi t ~ N^%.2f (%.0f -> %.0f it), "
                "CG-AMG t ~ N^%.2f (%.0f -> %.0f it)\n",
                g3.unknowns[a], g3.unknowns[b], power(g3.jacobi_ms), g3.jacobi_it[a],
                g3.jacobi_it[b], power(g3.amg_ms), g3.amg_it[a], g3.amg_it[b]);
  }
  const RandomNetwork p3 = packing_network(15, 15, 15, 1);
  run("3D 15^3 wide", widened(p3, 12, 3), 3);
  tolerance_sweep("3D 15^3", p3);
  tolerance_sweep("3D 15^3, g x 10^U(-6,6)", widened(p3, 12, 3));
  return 0;
}
