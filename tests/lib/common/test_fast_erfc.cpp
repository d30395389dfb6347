// SPDX-License-Identifier: GPL-2.0-or-later
// erfc_fast (src_fix/lib/common/fast_erfc.h) against glibc's std::erfc, the reference (within
// a few ulp by glibc's manual, "Errors in Math Functions"). The header promises 3e-14 relative
// up to x = 6 and 2e-13 up to 26 (its Chebyshev series' dropped terms add to 1.8e-15; the
// rounding of x^2 in the exponential's argument grows with x^2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/fast_erfc.h"

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
