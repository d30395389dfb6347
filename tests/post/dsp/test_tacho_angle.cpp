// SPDX-License-Identifier: GPL-2.0-or-later
// The shaft angle from a once-per-revolution pulse train (post/dsp/tacho_angle.h) against a
// run-up whose angle is known in closed form: the pulses are made where that angle passes 2 pi k.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "dsp/tacho_angle.h"
#include "synth.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;
constexpr double kFs = 20000;

// fr(t) = 20 + 10 t Hz over 1 s: theta(t) = 2 pi (20 t + 5 t^2), 25 revolutions
double theta_of(double t)
{
  return 2 * kPi * (20 * t + 5 * t * t);
}

// A 5 V keyphasor: rising over 2 deg of shaft angle (~4 samples) centred on each whole turn,
// high to 10 deg, falling over the next 2, with white noise of `noise` V.
std::vector<double> tacho(double noise, std::size_t n = static_cast<std::size_t>(kFs))
{
  test::Gaussian g(7);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double deg = std::remainder(theta_of(i / kFs), 2 * kPi) * 180 / kPi;
    const double up = std::clamp((deg + 1) / 2, 0.0, 1.0);
    const double down = std::clamp((11 - deg) / 2, 0.0, 1.0);
    x[i] = 5 * std::min(up, down) + noise * g();
  }
  return x;
}

// The time (s) the run-up's angle reaches 2 pi k.
double turn_time(int k)
{
  return (-20 + std::sqrt(400 + 20.0 * k)) / 10;
}

// The largest |angle - true angle| between the first edge (turn 1: the record starts halfway up
// turn 0's edge, which is not counted) and the last (turn 24), the angle's origin being turn 1's
// edge.
double worst_error(const TachoAngle &a)
{
  double worst = 0;
  for (auto i = static_cast<std::size_t>(std::ceil(turn_time(1) * kFs));
       i < static_cast<std::size_t>(turn_time(24) * kFs); ++i)
    worst = std::max(worst, std::fabs(a.theta[i] - (theta_of(i / kFs) - 2 * kPi)));
  return worst;
}

TEST(TachoAngle, FollowsARunUpWithinTheSpeedChangeOfARevolution)
{
  const TachoAngle a = angle_from_tacho(tacho(0.0));
  EXPECT_EQ(a.pulses, 24u);  // turns 1..24 within 0..1 s
  // linear within a revolution: the error is the speed's change over it, at most
  // 2 pi (dfr/dt) T^2 / 8 = 2 pi 10 (1/21)^2 / 8 = 0.018 rad in the first, plus the edge's
  // half-sample timing (2 pi 30 / 20000 / 2 = 0.005 rad at the end)
  EXPECT_LT(worst_error(a), 0.025);
  // before the first edge and after the last, the neighbouring revolution's speed: within the
  // speed's change over that stretch (0.05 s at 10 Hz/s: under 0.1 of a turn)
  EXPECT_NEAR(a.theta.front(), theta_of(0) - 2 * kPi, 0.1 * 2 * kPi);
  EXPECT_NEAR(a.theta.back(), theta_of((a.theta.size() - 1) / kFs) - 2 * kPi, 0.1 * 2 * kPi);
}

TEST(TachoAngle, NoiseOnTheEdgesCountsOnce)
{
  // 0.4 V of noise on a 5 V pulse rising over ~4 samples: more than one crossing of the middle
  // on some edges without the quarter-range re-arming; one pulse per revolution with it
  const TachoAngle a = angle_from_tacho(tacho(0.4));
  EXPECT_EQ(a.pulses, 24u);
  EXPECT_LT(worst_error(a), 0.03);
}

TEST(TachoAngle, RefusesAFlatChannelOrASinglePulse)
{
  EXPECT_THROW(angle_from_tacho(std::vector<double>(100, 1.0)), Error);
  EXPECT_THROW(angle_from_tacho({}), Error);
  try {
    angle_from_tacho(tacho(0.0, 1400));  // 0.07 s: one rising edge, turn 1's
    FAIL() << "one pulse accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("two or more"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ohmdem::post
