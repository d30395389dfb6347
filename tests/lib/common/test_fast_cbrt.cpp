// SPDX-License-Identifier: GPL-2.0-or-later
// The inline cube root of the hot loops (src_fix/lib/common/fast_cbrt.h) against libm's std::cbrt,
// which is the reference (correctly rounded to within 1 ulp in glibc).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "common/fast_cbrt.h"

namespace {

// Distance in units in the last place of `ref`.
double ulps(double value, double ref)
{
  const double ulp =
      std::nextafter(std::fabs(ref), std::numeric_limits<double>::infinity()) - std::fabs(ref);
  return std::fabs(value - ref) / ulp;
}

TEST(FastCbrt, WithinThreeUlpOverSixHundredDecades)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> decade(-300.0, 300.0), mantissa(1.0, 10.0);
  double worst = 0.0;
  for (int k = 0; k < 1000000; ++k) {
    const double x = mantissa(rng) * std::pow(10.0, decade(rng));
    worst = std::max(worst, ulps(ohmdem::cbrt_fast(x), std::cbrt(x)));
  }
  EXPECT_LE(worst, 3.0);
}

TEST(FastCbrt, ExactCubesAndTheForcesOfABearing)
{
  for (double r : {1.0, 2.0, 3.0, 10.0, 0.5, 1e-3, 123.0})
    EXPECT_LE(ulps(ohmdem::cbrt_fast(r * r * r), r), 3.0);
  // Products of two ball–race forces (N^2), the argument in the closed-form resistance.
  for (double q : {1e-12, 3.7e-6, 1.0, 625.0, 2.5e3, 1e8})
    EXPECT_LE(ulps(ohmdem::cbrt_fast(q), std::cbrt(q)), 3.0) << q;
}

TEST(FastCbrt, EdgeArgumentsAreLibmsAnswers)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double sub = std::numeric_limits<double>::denorm_min();
  for (double x :
       {0.0, -0.0, -8.0, -1e-5, sub, 1e-310, 1e301, std::numeric_limits<double>::max(), inf, -inf})
    EXPECT_EQ(ohmdem::cbrt_fast(x), std::cbrt(x)) << x;
  EXPECT_TRUE(std::isnan(ohmdem::cbrt_fast(std::nan(""))));
  // The bounds of the fast range stay accurate.
  EXPECT_LE(ulps(ohmdem::cbrt_fast(2.3e-308), std::cbrt(2.3e-308)), 3.0);
  EXPECT_LE(ulps(ohmdem::cbrt_fast(1e300), std::cbrt(1e300)), 3.0);
}

}  // namespace
