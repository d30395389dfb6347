// SPDX-License-Identifier: GPL-2.0-or-later
// erfc_fast (src_fix/lib/common/fast_erfc.h) against glibc's std::erfc, the reference (within
// a few ulp by glibc's manual, "Errors in Math Functions"). The header promises 3e-14 relative
// up to x = 6 and 2e-13 up to 26 (its Chebyshev series' dropped terms add to 1.8e-15; the
// rounding of x^2 in the exponential's argument grows with x^2). Also the Estrin form that
// sums its series (common/estrin.h) and exp_small (lubrication/exp_small.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>

#include "common/estrin.h"
#include "common/fast_erfc.h"
#include "lubrication/exp_small.h"

TEST(FastErfc, WithinItsBoundOverTheMetallicFractionsRange)
{
  // x = lambda / sqrt(2): lambda from 0 to 35 covers every film the contact evaluates erfc
  // for (beyond, erfc < 1e-260 is skipped or underflows).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 26.0), small(-12.0, 0.0);
  double worst = 0.0, where = 0.0, worst6 = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    const double x = i % 4 == 0 ? std::pow(10.0, small(rng)) : u(rng);
    const double want = std::erfc(x), got = ohmdem::erfc_fast(x);
    const double rel = std::fabs(got / want - 1.0);
    if (rel > worst) worst = rel, where = x;
    if (x <= 6.0) worst6 = std::fmax(worst6, rel);
  }
  std::printf("worst relative difference %.2e at x = %.6g, %.2e up to x = 6\n", worst, where,
              worst6);
  EXPECT_LT(worst6, 3e-14);
  EXPECT_LT(worst, 2e-13);
}

TEST(FastErfc, NearOneAsGlibcWhereLambdaIsSmall)
{
  // Below x = 0.5, 1 - erf(x) by erf's series: within an ulp of 1 of glibc's, so that the
  // non-metallic fraction 1 - f of a film of nearly nothing is the same to rounding (the
  // regime test's Rb = R at sigma = 1e-3 m, tests/decks/lubricated_validation.py).
  double worst = 0.0;
  for (double x = 1e-17; x < 0.5; x *= 1.01)
    worst = std::fmax(worst, std::fabs(ohmdem::erfc_fast(x) - std::erfc(x)));
  std::printf("worst absolute difference below x = 0.5: %.2e\n", worst);
  EXPECT_LE(worst, 1.2e-16);
}

TEST(FastErfc, ExactWhereTheDryLimitNeedsIt)
{
  EXPECT_EQ(ohmdem::erfc_fast(0.0), 1.0);   // a metallic fraction of exactly 1
  EXPECT_EQ(ohmdem::erfc_fast(-0.0), 1.0);  // -0.0 == 0.0
  EXPECT_EQ(ohmdem::erfc_fast(-1.0), std::erfc(-1.0));
  EXPECT_EQ(ohmdem::erfc_fast(30.0), std::erfc(30.0));
  EXPECT_TRUE(std::isnan(ohmdem::erfc_fast(NAN)));
}

// common/estrin.h, which sums erfc_fast's series (and the lubricated contact's other
// polynomials): against Horner's rule in long double (64-bit mantissa, the reference), for
// every length up to erfc's 22 terms. A sum of N terms in double is within ~N ulp of
// sum |c_k x^k| (the bound of any order of summation); the lane form gives the scalar's bits.
template <int N>
static void check_estrin(std::mt19937_64 &rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  typedef double v4d __attribute__((vector_size(32)));
  for (int trial = 0; trial < 200; ++trial) {
    double c[N];
    v4d cv[N];
    for (int k = 0; k < N; ++k) c[k] = u(rng), cv[k] = v4d{c[k], c[k], c[k], c[k]};
    const v4d xs = {u(rng), u(rng), 2.0 * u(rng), 0.0};
    const v4d lanes = ohmdem::estrin::polynomial<N>(cv, xs);
    for (int l = 0; l < 4; ++l) {
      const double x = xs[l], got = ohmdem::estrin::polynomial<N>(c, x);
      long double want = c[N - 1], scale = 0.0L;
      for (int k = N - 2; k >= 0; --k) want = want * x + c[k];
      for (int k = 0; k < N; ++k) scale += std::fabs(c[k]) * std::pow(std::fabs(x), k);
      ASSERT_LE(std::fabs(static_cast<long double>(got) - want), 2.0L * N * 0x1p-53L * scale)
          << "N = " << N << ", x = " << x;
      ASSERT_EQ(lanes[l], got) << "N = " << N << ", lane " << l;  // the same bits
    }
  }
}

template <int... N>
static void check_estrin_lengths(std::mt19937_64 &rng, std::integer_sequence<int, N...>)
{
  (check_estrin<N + 1>(rng), ...);
}

TEST(Estrin, WithinRoundingOfHornerInLongDoubleForEveryLength)
{
  std::mt19937_64 rng(5);
  check_estrin_lengths(rng, std::make_integer_sequence<int, 22>{});
}

TEST(Estrin, ExpSmallWithinAnUlpOfGlibc)
{
  // exp_small (lubrication/exp_small.h): e^z for |z| < 0.25, the Taylor series to z^13.
  double worst = 0.0;
  for (double z = -0.25; z < 0.25; z += 1e-5)
    worst = std::fmax(worst, std::fabs(ohmdem::lubrication::exp_small(z) / std::exp(z) - 1.0));
  std::printf("exp_small: worst relative difference %.2e\n", worst);
  EXPECT_LE(worst, 3.4e-16);  // 1.5 ulp above 1 (the reference's own ~0.5 included)
}
