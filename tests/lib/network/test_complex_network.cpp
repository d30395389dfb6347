// SPDX-License-Identifier: GPL-2.0-or-later
// The complex admittance network (network/complex_network.*) against circuits solved by
// hand (series and parallel admittances, y1 y2 / (y1 + y2) and y1 + y2) and against a dense
// Gaussian elimination in long double written here (not Eigen): disconnected nodes, twelve
// decades and more between admittances, purely capacitive networks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "network/complex_network.h"
#include "network/network_export.h"
#include "network_test_utils.h"
#include "temp_dir.h"

using namespace ohmdem;
using cplx = std::complex<double>;

namespace {

constexpr NodeKey kHigh = 1000, kLow = 7;

double rel(cplx a, cplx b)
{
  return std::abs(a - b) / std::abs(b);
}

cplx series(cplx a, cplx b)
{
  return a * b / (a + b);
}

// Z by a dense nodal solve in long double with partial pivoting; nodes 0..n-1, n-1 grounded,
// current 1 into node 0.
std::complex<long double> dense_z(int n, const std::vector<std::array<long double, 4>> &e)
{
  using lc = std::complex<long double>;
  const int m = n - 1;
  std::vector<std::vector<lc>> a(m, std::vector<lc>(m + 1, lc(0)));
  for (const auto &x : e) {
    const int i = static_cast<int>(x[0]), j = static_cast<int>(x[1]);
    const lc y(x[2], x[3]);
    if (i < m) a[i][i] += y;
    if (j < m) a[j][j] += y;
    if (i < m && j < m) a[i][j] -= y, a[j][i] -= y;
  }
  a[0][m] = 1;
  for (int c = 0; c < m; ++c) {
    int p = c;
    for (int r = c + 1; r < m; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    for (int r = c + 1; r < m; ++r) {
      const lc f = a[r][c] / a[c][c];
      for (int k = c; k <= m; ++k) a[r][k] -= f * a[c][k];
    }
  }
  std::vector<lc> v(m);
  for (int r = m - 1; r >= 0; --r) {
    lc s = a[r][m];
    for (int k = r + 1; k < m; ++k) s -= a[r][k] * v[k];
    v[r] = s / a[r][r];
  }
  return v[0];
}

// A mesh of n nodes (0 high, n - 1 low): a chain plus chords, G = g0 10^U(-d, d) and
// omega C = c0 10^U(-d, d); both as edges and as rows {i, j, G, omega C} for dense_z.
void random_mesh(int n, std::uint64_t seed, double d, double g0, double c0,
                 std::vector<std::array<long double, 4>> &dense, std::vector<ComplexEdge> &e)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-d, d);
  auto key = [&](int i) { return i == 0 ? kHigh : i == n - 1 ? kLow : NodeKey(100 + i); };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (j == i + 1 || (i * 5 + j * 3) % 7 == 0) {
        const double g = g0 * std::pow(10.0, u(rng)), c = c0 * std::pow(10.0, u(rng));
        dense.push_back({static_cast<long double>(i), static_cast<long double>(j), g, c});
        e.push_back({key(i), key(j), {g, c}});
      }
}

}  // namespace

TEST(ComplexNetwork, SeriesAndParallelByHand)
{
  const cplx y1(2e-3, 5e-4), y2(1e-6, 3e-3), y3(0.0, 7e-5);
  // high -y1- m -y2- low, and y3 from high to low.
  const std::vector<ComplexEdge> e{{kHigh, 42, y1}, {42, kLow, y2}, {kHigh, kLow, y3}};
  const ComplexSolution s = solve_complex_network(e, kHigh, kLow, 0.1);
  EXPECT_TRUE(s.connected);
  EXPECT_EQ(s.unknowns, 1);  // the middle node eliminated in series
  EXPECT_EQ(s.eliminated, 1);
  const cplx z = 1.0 / (series(y1, y2) + y3);
  EXPECT_LT(rel(s.z, z), 1e-14);
  // The middle node: the current through y1 is y1 (v_high - v_m) = series(y1, y2) v_high.
  const cplx vh = s.potential(kHigh), vm = s.potential(42);
  EXPECT_LT(rel(y1 * (vh - vm), series(y1, y2) * vh), 1e-13);
  EXPECT_EQ(s.potential(kLow), cplx(0.0, 0.0));
}

TEST(ComplexNetwork, ParallelEdgesAndOrder)
{
  // Two balls of two contacts each, given twice in opposite orders: the same bits.
  std::vector<ComplexEdge> e{{kHigh, 1, {1e-4, 2e-6}}, {1, kLow, {3e-4, 1e-6}},
                             {kHigh, 2, {0.0, 5e-6}},  {2, kLow, {2e-9, 4e-6}},
                             {kHigh, kLow, {1e-8, 0}}, {kLow, kHigh, {2e-8, 0}}};
  const ComplexSolution a = solve_complex_network(e, kHigh, kLow, 1.0);
  std::reverse(e.begin(), e.end());
  const ComplexSolution b = solve_complex_network(e, kHigh, kLow, 1.0);
  EXPECT_EQ(a.z, b.z);
  const cplx y = series({1e-4, 2e-6}, {3e-4, 1e-6}) + series({0.0, 5e-6}, {2e-9, 4e-6}) + 3e-8;
  EXPECT_LT(rel(a.z, 1.0 / y), 1e-13);
}

TEST(ComplexNetwork, DisconnectedNodes)
{
  // An island (5-6), a node joined only by a zero admittance (9), an edge between two
  // floating nodes: Z is the connected part's, the floating potentials are 0.
  const cplx y(1e-3, 1e-3);
  const std::vector<ComplexEdge> e{
      {kHigh, kLow, y}, {5, 6, {1.0, 0.0}}, {kHigh, 9, {0.0, 0.0}}, {9, 5, {2.0, 1.0}}};
  const ComplexSolution s = solve_complex_network(e, kHigh, kLow, 0.5);
  EXPECT_TRUE(s.connected);
  EXPECT_EQ(s.unknowns, 1);
  EXPECT_LT(rel(s.z, 1.0 / y), 1e-15);
  for (NodeKey k : {5, 6, 9}) EXPECT_EQ(s.potential(k), cplx(0.0, 0.0)) << k;
  // No path at all: Z = +inf, never a NaN.
  const ComplexSolution none = solve_complex_network({{kHigh, 3, y}}, kHigh, kLow, 0.5);
  EXPECT_FALSE(none.connected);
  EXPECT_TRUE(std::isinf(none.z.real()));
  EXPECT_EQ(none.z.imag(), 0.0);
}

TEST(ComplexNetwork, HugeContrasts)
{
  // 1e-15 S in series with 1e3 S: Z = 1e15 + 1e-3 ohm, with and without the elimination of
  // the series node; in parallel: Z = 1 / (1e3 + 1e-15).
  for (bool reduce : {true, false}) {
    ComplexOptions o;
    o.reduce_series = reduce;
    const ComplexSolution s =
        solve_complex_network({{kHigh, 3, {1e-15, 0}}, {3, kLow, {1e3, 0}}}, kHigh, kLow, 1.0, o);
    EXPECT_EQ(s.eliminated, reduce ? 1 : 0);
    EXPECT_LT(rel(s.z, cplx(1e15 + 1e-3, 0.0)), 1e-14) << reduce;
    const ComplexSolution p = solve_complex_network(
        {{kHigh, kLow, {1e-15, 0}}, {kHigh, kLow, {1e3, 0}}}, kHigh, kLow, 1.0, o);
    EXPECT_EQ(p.z, cplx(1.0 / (1e3 + 1e-15), 0.0));
  }
  // A metallic contact (1e3 S) in series with an idle gap (1e-15 j S) next to a capacitor:
  // the nodal matrix alone would lose the gap (1e3 - 1e6 / (1e3 + 1e-15 j) cancels), the
  // series elimination keeps it.
  const cplx big(1e3, 0.0), gap(0.0, 1e-15), film(0.0, 3e-15);
  const ComplexSolution b = solve_complex_network(
      {{kHigh, 3, big}, {3, kLow, gap}, {kHigh, kLow, film}}, kHigh, kLow, 1.0);
  EXPECT_LT(rel(b.z, 1.0 / (series(big, gap) + film)), 1e-14);
  // A Wheatstone bridge (no node of degree 2: the LU solves it): H-a 1e3, H-b 1e-15,
  // a-L 1e-15, b-L 1e3, a-b 1 + 1e-12 j S. The dense long-double solve is the reference.
  const cplx yab(1.0, 1e-12);
  const ComplexSolution w = solve_complex_network({{kHigh, 10, big},
                                                   {kHigh, 11, {1e-15, 0}},
                                                   {10, kLow, {1e-15, 0}},
                                                   {11, kLow, big},
                                                   {10, 11, yab}},
                                                  kHigh, kLow, 1.0);
  EXPECT_EQ(w.unknowns, 3);
  const std::complex<long double> zr = dense_z(
      4,
      {{0, 1, 1e3L, 0}, {0, 2, 1e-15L, 0}, {1, 3, 1e-15L, 0}, {2, 3, 1e3L, 0}, {1, 2, 1, 1e-12L}});
  EXPECT_LT(rel(w.z, cplx(double(zr.real()), double(zr.imag()))), 1e-12) << w.z;
  // A random mesh, admittances over 8 decades (G and C), without and with the elimination,
  // against the dense reference.
  std::vector<std::array<long double, 4>> dense;
  std::vector<ComplexEdge> e;
  random_mesh(40, 11, 4.0, 1.0, 1e-3, dense, e);
  const std::complex<long double> zm = dense_z(40, dense);
  for (bool reduce : {true, false}) {
    ComplexOptions o;
    o.reduce_series = reduce;
    const ComplexSolution l = solve_complex_network(e, kHigh, kLow, 1.0, o);
    EXPECT_GT(l.unknowns, 20);
    EXPECT_LT(rel(l.z, cplx(double(zm.real()), double(zm.imag()))), 1e-12) << l.z;
  }
}

TEST(ComplexNetwork, PurelyCapacitive)
{
  // Two capacitors in series, a third in parallel with the second: C = C1 (C2 + C3) / (...).
  const double w = 2 * M_PI * 1e4, c1 = 40e-12, c2 = 60e-12, c3 = 5e-12;
  const ComplexSolution s = solve_complex_network(
      {{kHigh, 4, {0, w * c1}}, {4, kLow, {0, w * c2}}, {4, kLow, {0, w * c3}}}, kHigh, kLow, 0.1);
  const double c = c1 * (c2 + c3) / (c1 + c2 + c3);
  EXPECT_LT(rel(s.z, cplx(0.0, -1.0 / (w * c))), 1e-14);
  EXPECT_NEAR(std::arg(s.z), -M_PI / 2, 1e-14);
  // A random capacitive mesh over 6 decades against the dense reference.
  const int n = 30;
  std::vector<std::array<long double, 4>> dense;
  std::vector<ComplexEdge> e;
  random_mesh(n, 5, 3.0, 0.0, 1e-9, dense, e);
  const ComplexSolution m = solve_complex_network(e, kHigh, kLow, 1.0);
  const std::complex<long double> zr = dense_z(n, dense);
  EXPECT_LT(rel(m.z, cplx(double(zr.real()), double(zr.imag()))), 1e-12);
  EXPECT_NEAR(std::arg(m.z), -M_PI / 2, 1e-12);
}

TEST(ComplexNetwork, BadInput)
{
  const cplx y(1.0, 0.0);
  EXPECT_THROW(solve_complex_network({{1, 2, y}}, 1, 1, 1.0), std::invalid_argument);
  EXPECT_THROW(solve_complex_network({{3, 3, y}}, 1, 2, 1.0), std::invalid_argument);
  EXPECT_THROW(solve_complex_network({{1, 2, {NAN, 0}}}, 1, 2, 1.0), std::invalid_argument);
  EXPECT_THROW(solve_complex_network({{1, 2, y}}, 1, 2, 0.0), std::invalid_argument);
}

// The AC netlist (network_export.h) of a mesh with resistors, capacitors, a capacitor-only
// node (no DC path but rshunt's) and a floating island, run by ngspice's .ac analysis: its
// own parsing and MNA solve give V(ehigh) = Z I to 1e-9 of ours (skipped without ngspice).
TEST(ComplexNetwork, AcNetlistAgainstNgspice)
{
  if (!ohmdem_test::have_ngspice()) GTEST_SKIP() << "ngspice is not installed";
  std::vector<std::array<long double, 4>> dense;
  std::vector<ComplexEdge> e;
  const double omega = 2 * M_PI * 1e4;
  random_mesh(25, 3, 3.0, 1e-6, 1e-6, dense, e);
  e.push_back({kHigh, 77, {0.0, 3e-7}});
  e.push_back({77, kLow, {0.0, 5e-7}});
  e.push_back({88, 89, {1e-3, 1e-6}});
  const double current = 0.1;
  const ComplexSolution s = solve_complex_network(e, kHigh, kLow, current);
  namespace fs = std::filesystem;
  const fs::path dir = ohmdem::test::temp_dir() / "ngspice_ac";
  fs::create_directories(dir);
  {
    std::ofstream f(dir / "ac.cir");
    write_spice_ac_netlist(f, e, kHigh, kLow, current, omega,
                           [](NodeKey k) { return "n" + std::to_string(k); });
  }
  const std::string cmd =
      "cd '" + dir.string() + "' && SPICE_ASCIIRAWFILE=1 ngspice -b -r ac.raw ac.cir > ng.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream in(dir / "ac.raw");
  std::string line;
  int var = -1, k = -1;
  bool values = false;
  cplx v(NAN, NAN);
  while (std::getline(in, line)) {
    if (line.rfind("Values:", 0) == 0) values = true;
    std::istringstream ls(line);
    int i;
    std::string name;
    if (!values && !line.empty() && line[0] == '\t' && (ls >> i >> name) && name == "v(ehigh)")
      var = i;
    if (values && k++ == var) {
      double re, im;
      char comma;
      std::istringstream vs(line);
      if (vs >> re >> comma >> im) v = {re, im};
    }
  }
  ASSERT_GE(var, 0);
  std::printf("[ info ] Z = %.15g%+.15gj, ngspice %.15g%+.15gj\n", s.z.real(), s.z.imag(),
              v.real() / current, v.imag() / current);
  EXPECT_LT(rel(v / current, s.z), 1e-9);
}
