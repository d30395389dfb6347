// SPDX-License-Identifier: GPL-2.0-or-later
// Independent check with a circuit simulator: the exported netlist is run by `ngspice -b`
// (Debian package ngspice; CI installs it) and V(ehigh) / I must equal our R to 1e-9.
// ngspice factorizes the full MNA system with its own sparse LU, without our reduction,
// scaling or ordering, and parses every R element itself (parallel edges included).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "network/conduction_network.h"
#include "network_test_utils.h"

using namespace ohmdem;
using namespace ohmdem_test;

namespace {

void compare_with_ngspice(const RandomNetwork &rn, const std::string &name, SolverKind kind)
{
  if (!have_ngspice()) GTEST_SKIP() << "ngspice is not installed (apt-get install ngspice)";
  ConductionNetwork net;
  SolverOptions o;
  o.kind = kind;
  o.cg_max_iterations = 100000;  // no fallback to the direct solve: test CG itself
  net.set_options(o);
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  add_all(net, rn.edges);
  const double I = 0.1;
  const NetworkSolution s = net.solve(I);
  std::string err;
  const double v = ngspice_ehigh_voltage(net, I, name, err);
  ASSERT_TRUE(std::isfinite(v)) << err;
  const double r_spice = v / I;
  const double rel = std::fabs(s.resistance - r_spice) / r_spice;
  std::printf("[ info ] %s: R = %.15g ohm, ngspice %.15g, rel. diff %.2e (%d unknowns)\n",
              name.c_str(), s.resistance, r_spice, rel, s.unknowns);
  EXPECT_LT(rel, 1e-9);
  if (kind == SolverKind::Direct) {
    EXPECT_EQ(s.method, SolveMethod::Direct);
  } else if (kind == SolverKind::ConjugateGradient) {
    EXPECT_EQ(s.method, SolveMethod::ConjugateGradient);
  }
}

}  // namespace

TEST(Ngspice, RandomNetworkOneDecade)
{
  compare_with_ngspice(random_network(300, 600, -0.5, 0.5, 17), "random_1dec", SolverKind::Direct);
}

TEST(Ngspice, RandomNetworkTwelveDecades)
{
  // Conductances log-uniform over 1e-6 .. 1e6 S.
  compare_with_ngspice(random_network(300, 600, -6, 6, 18), "random_12dec_direct",
                       SolverKind::Direct);
  compare_with_ngspice(random_network(300, 600, -6, 6, 18), "random_12dec_cg",
                       SolverKind::ConjugateGradient);
}

TEST(Ngspice, PackingNetwork2D)
{
  compare_with_ngspice(packing_network(14, 14, 1, 5), "packing2d", SolverKind::Auto);
}

TEST(Ngspice, PackingNetworkTwelveDecades)
{
  // The 2D packing with every conductance multiplied by 10^U(-6, 6): an ill-conditioned
  // system (CG needs ~10x more iterations than on the plain packing).
  const RandomNetwork rn = widened(packing_network(14, 14, 1, 6), 12, 9);
  compare_with_ngspice(rn, "packing2d_12dec_direct", SolverKind::Direct);
  compare_with_ngspice(rn, "packing2d_12dec_cg", SolverKind::ConjugateGradient);
}

TEST(Ngspice, FloatingClusterIsCommentedOut)
{
  // A floating cluster would make ngspice's matrix singular; the netlist comments it out.
  RandomNetwork rn = random_network(200, 300, -2, 2, 19);
  const RandomNetwork other = random_network(30, 10, -2, 2, 20);
  rn.edges.insert(rn.edges.end(), other.edges.begin(), other.edges.end());
  compare_with_ngspice(rn, "floating", SolverKind::ConjugateGradient);
}
