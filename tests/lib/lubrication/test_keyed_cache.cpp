// SPDX-License-Identifier: GPL-2.0-or-later
// The cached constants of the lubrication kernels (src_fix/lib/lubrication/keyed_cache.h and
// its uses in ehl_film.cpp and contact_admittance.cpp): the cache returns what make() gives,
// and the kernels that use it agree to 1e-12 with the formulas evaluated the plain way here
// (std::pow, a logarithm and a division per quadrature angle, the permittivity of each node
// from permittivity_at_pressure), over loads, speeds and geometries that evict cached keys.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lubrication/contact_admittance.h"
#include "lubrication/ehl_film.h"
#include "lubrication/keyed_cache.h"
#include "test_constants.h"

using namespace ohmdem::lubrication;
using ohmdem::test::kPi;

namespace {

// The gap integral as written in contact_admittance.h, term by term.
double plain_gap(const GapGeometry &g, double eps_r)
{
  const int n = 32;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double c = std::cos((i + 0.5) * (0.5 * kPi / n)), c2 = c * c, s2 = 1.0 - c2;
    const double s_in2 = g.a > 0.0 && g.b > 0.0
                             ? 1.0 / (2.0 * g.rx * c2 / (g.b * g.b) + 2.0 * g.ry * s2 / (g.a * g.a))
                             : 0.0;
    const double s_out2 = g.r_wet * g.r_wet / (2.0 * g.rx * c2 + 2.0 * g.ry * s2);
    if (s_out2 > s_in2) sum += std::log((g.h0 + s_out2) / (g.h0 + s_in2));
  }
  return kEpsilon0 * eps_r * std::sqrt(g.rx * g.ry) * sum * (2.0 * kPi / n);
}

double plain_mean_permittivity(double eps_r, double p0)
{
  const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                       0.9602898564975363};
  const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                       0.1012285362903763};
  double s = 0.0;
  for (int i = 0; i < 4; ++i)
    for (const double t : {0.5 * (1.0 - x[i]), 0.5 * (1.0 + x[i])})
      s += w[i] * t * permittivity_at_pressure(eps_r, p0 * t);
  return s;
}

Film plain_film(const FilmInput &in)
{
  const double U = in.eta * in.speed / (in.e_prime * in.rx), G = in.alpha * in.e_prime,
               W = in.load / (in.e_prime * in.rx * in.rx);
  return {in.rx * 2.69 * std::pow(U, 0.67) * std::pow(G, 0.53) * std::pow(W, -0.067) *
              (1.0 - 0.61 * std::exp(-0.73 * in.k)),
          in.rx * 3.63 * std::pow(U, 0.68) * std::pow(G, 0.49) * std::pow(W, -0.073) *
              (1.0 - std::exp(-0.68 * in.k))};
}

double rel(double a, double b)
{
  return std::fabs(a / b - 1.0);
}

}  // namespace

TEST(KeyedCache, ReturnsWhatMakeGivesAndEvicts)
{
  KeyedCache<2, double, 2> cache;
  int made = 0;
  auto sum = [&made](const std::array<double, 2> &k) {
    ++made;
    return k[0] + k[1];
  };
  EXPECT_EQ(cache.get({1.0, 2.0}, sum), 3.0);
  EXPECT_EQ(cache.get({1.0, 2.0}, sum), 3.0);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(cache.get({2.0, 2.0}, sum), 4.0);
  EXPECT_EQ(cache.get({3.0, 2.0}, sum), 5.0);  // evicts {1, 2}
  EXPECT_EQ(cache.get({1.0, 2.0}, sum), 3.0);
  EXPECT_EQ(made, 4);
  EXPECT_TRUE(std::isnan(cache.get({NAN, 0.0}, sum)));  // a NaN key is made each time
  cache.get({NAN, 0.0}, sum);
  EXPECT_EQ(made, 6);
}

TEST(KeyedCache, KernelsAgreeWithThePlainFormulas)
{
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto logu = [&](double lo, double hi) { return lo * std::pow(hi / lo, u01(rng)); };
  // The gap: in closed form while the wetted circle holds the Hertz ellipse, else angle by angle.
  double worst_film = 0, worst_gap[2] = {0, 0}, worst_idle = 0, worst_eps = 0;
  int cases[2] = {0, 0};
  for (int n = 0; n < 4000; ++n) {
    // Six races and three oils in turn: more keys than the caches hold.
    const double rx = 2e-3 + 1e-3 * (n % 6), ry = 10.0 * rx + 0.05 * (n % 5);
    FilmInput f{logu(0.1, 5e3),   logu(1e-3, 50.0),    rx, ry, 2.2e11, logu(1e-3, 1.0),
                logu(1e-8, 3e-8), 1.0 + 9.0 * u01(rng)};
    const Film a = hamrock_dowson(f), b = plain_film(f);
    worst_film =
        std::fmax(worst_film, std::fmax(rel(a.central, b.central), rel(a.minimum, b.minimum)));
    const double c = std::cbrt(f.load) * 1e-4;  // Hertz-like semi-axes
    const GapGeometry g{logu(1e-8, 1e-5), rx, ry, c * f.k, c, logu(2e-4, 5e-3)};
    const int closed = g.r_wet > g.a && g.r_wet > g.b;
    ++cases[closed];
    worst_gap[closed] =
        std::fmax(worst_gap[closed], rel(gap_capacitance(g, 2.1), plain_gap(g, 2.1)));
    const GapGeometry idle{logu(1e-8, 1e-4), rx, ry, 0.0, 0.0, g.r_wet};
    worst_idle = std::fmax(worst_idle, rel(gap_capacitance(idle, 2.1), plain_gap(idle, 2.1)));
    const double p0 = logu(1e7, 4e9), eps = 2.0 + u01(rng);
    worst_eps = std::fmax(worst_eps,
                          rel(hertz_mean_permittivity(eps, p0), plain_mean_permittivity(eps, p0)));
  }
  EXPECT_LT(worst_film, 1e-12);
  EXPECT_LT(worst_gap[0], 1e-12);
  EXPECT_LT(worst_gap[1], 1e-12);
  EXPECT_GT(cases[0], 500);
  EXPECT_GT(cases[1], 500);
  EXPECT_LT(worst_idle, 1e-12);
  EXPECT_LT(worst_eps, 1e-12);
  std::printf(
      "worst relative differences: film %.2e, gap %.2e (closed form, %d cases), "
      "%.2e (by angle, %d), idle gap %.2e, eps %.2e\n",
      worst_film, worst_gap[1], cases[1], worst_gap[0], cases[0], worst_idle, worst_eps);
  // A product that overflows (a gap of 1e-300 m) takes the logarithm per angle.
  const GapGeometry tiny{1e-300, 5e-3, 0.1, 0.0, 0.0, 1e-3};
  EXPECT_LT(rel(gap_capacitance(tiny, 2.0), plain_gap(tiny, 2.0)), 1e-12);
}

TEST(KeyedCache, SeriesWithoutTheGeneralDivision)
{
  const std::complex<double> y1{1e-11, 3e-6}, y2{2e-12, 7e-7};
  const std::complex<double> s = series(y1, y2), ref = y1 * y2 / (y1 + y2);
  EXPECT_LT(std::abs(s / ref - 1.0), 1e-15);
}
