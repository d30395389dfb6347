// SPDX-License-Identifier: GPL-2.0-or-later
// Where a record's level settles (post/dsp/settle.h): a stationary record is settled from its
// first sample; a record whose first windows sit off the level (a known offset, or an
// exponential drift whose crossing of the 6-scatter limit is known in closed form) settles at
// the first window of three within the limit.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "dsp/settle.h"
#include "synth.h"

namespace ohmdem::post {
namespace {

constexpr std::size_t kWindow = 250;  // one revolution of 80 Hz at 20 kHz

// a modulation of 5.15 periods per window (a BPFO-like line) and white noise
std::vector<double> stationary(std::size_t windows, double noise, unsigned seed = 3)
{
  test::Gaussian g(seed);
  std::vector<double> x(windows * kWindow);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 1 + 0.01 * std::sin(2 * 3.141592653589793 * 5.15 * static_cast<double>(i) / kWindow) +
           noise * g();
  return x;
}

TEST(Settle, StationaryRecordSettledFromTheStart)
{
  const Settling st = settled_start(stationary(40, 1e-3), kWindow);
  EXPECT_EQ(st.start, 0u);
  EXPECT_NEAR(st.level, 1, 1e-3);
}

TEST(Settle, OffsetWindowsSkipped)
{
  std::vector<double> x = stationary(40, 1e-3);
  for (std::size_t i = 0; i < 5 * kWindow; ++i) x[i] += 0.01;  // 5 windows 10 x the noise off
  EXPECT_EQ(settled_start(x, kWindow).start, 5 * kWindow);
}

TEST(Settle, ExponentialDriftSkippedUntilWithinTheLimit)
{
  std::vector<double> x = stationary(40, 1e-3);
  // the window means' scatter (measured on the record's second half) is about 1e-3 /
  // sqrt(250) plus the modulation's leak; the drift 0.02 exp(-t / 2 windows) falls below 6
  // scatters after a known number of windows: the settled start is the first window whose
  // mean drift lies within the limit, computed here from the returned scatter
  const double tau = 2.0 * kWindow;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.02 * std::exp(-static_cast<double>(i) / tau);
  const Settling st = settled_start(x, kWindow);
  std::size_t expect = 0;
  for (;; ++expect) {  // window mean of the drift: closed form of the exponential's integral
    const double a = static_cast<double>(expect * kWindow), b = a + kWindow;
    const double mean = 0.02 * tau * (std::exp(-a / tau) - std::exp(-b / tau)) / kWindow;
    if (mean <= kSettleSigmas * st.scatter) break;
  }
  EXPECT_NEAR(static_cast<double>(st.start / kWindow), static_cast<double>(expect), 1.0);
  EXPECT_GT(st.start, 0u);
}

TEST(Settle, NeverPastTheMiddle)
{
  std::vector<double> x = stationary(20, 1e-3);
  for (std::size_t i = 0; i < 15 * kWindow; ++i) x[i] += 0.05;
  EXPECT_LE(settled_start(x, kWindow).start, 10 * kWindow);
}

TEST(Settle, ShortRecordOrBadWindow)
{
  EXPECT_EQ(settled_start(stationary(7, 1e-3), kWindow).start, 0u);
  EXPECT_THROW(settled_start(stationary(10, 1e-3), 1), Error);
}

}  // namespace
}  // namespace ohmdem::post
