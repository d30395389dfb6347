// SPDX-License-Identifier: GPL-2.0-or-later
// log_fast and exp_fast (src_fix/lib/common/fast_exp_log.h) against glibc's std::log and
// std::exp, the reference: correctly rounded to within 1 ulp by glibc's own documentation
// (the manual's "Errors in Math Functions" table lists 1 ulp for log and exp on x86_64).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "common/fast_exp_log.h"

namespace {

// Distance in units of the last place of the reference.
double ulps(double got, double want)
{
  return std::fabs(got - want) / (std::nextafter(std::fabs(want), HUGE_VAL) - std::fabs(want));
}

TEST(FastExpLog, LogWithinFourUlpOverEveryDecade)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> decade(-300.0, 300.0);
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    const double x = std::pow(10.0, decade(rng));
    worst = std::max(worst, ulps(ohmdem::log_fast(x), std::log(x)));
  }
  EXPECT_LE(worst, 4.0);
}

TEST(FastExpLog, LogNearOneKeepsItsRelativeAccuracy)
{
  // ln x -> 0 at x = 1: the error must shrink with it (relative, not absolute, accuracy).
  for (double d = 1e-15; d < 0.5; d *= 1.37) {
    EXPECT_LE(ulps(ohmdem::log_fast(1.0 + d), std::log(1.0 + d)), 4.0) << d;
    EXPECT_LE(ulps(ohmdem::log_fast(1.0 - d), std::log(1.0 - d)), 4.0) << d;
  }
  EXPECT_EQ(ohmdem::log_fast(1.0), 0.0);
}

TEST(FastExpLog, ExpWithinFourUlpOverItsRange)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> arg(-700.0, 700.0), small(-2.0, 2.0);
  double worst = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    const double x = i % 2 ? arg(rng) : small(rng);
    worst = std::max(worst, ulps(ohmdem::exp_fast(x), std::exp(x)));
  }
  EXPECT_LE(worst, 4.0);
  EXPECT_EQ(ohmdem::exp_fast(0.0), 1.0);
}

TEST(FastExpLog, OutOfRangeArgumentsGoToTheLibrary)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ohmdem::log_fast(0.0), -inf);
  EXPECT_TRUE(std::isnan(ohmdem::log_fast(-1.0)));
  EXPECT_EQ(ohmdem::log_fast(inf), inf);
  EXPECT_EQ(ohmdem::log_fast(4e-320), std::log(4e-320));
  EXPECT_EQ(ohmdem::exp_fast(-800.0), 0.0);
  EXPECT_EQ(ohmdem::exp_fast(800.0), inf);
  EXPECT_TRUE(std::isnan(ohmdem::exp_fast(std::nan(""))));
}

}  // namespace
