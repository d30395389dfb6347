// SPDX-License-Identifier: GPL-2.0-or-later
// The outer pit's angle from the load direction (post/bearing/outer_position.h) on synthetic
// records: a level with a ball-pass modulation (its maximum: a ball on the load line) and
// pulses centred where a ball reaches a pit theta degrees further along the race, so the pulse
// follows the maximum by Nb * theta of the ball-pass cycle (the kinematics the estimator
// inverts), made at 1 MHz and acquired through dsp/acquire's chain (Butterworth order 4 at
// 0.4 x rate, then sampling, noise). The chain delays the modulation and the pulse alike (its
// group delay, flat far below the cut-off), so the reference is theta itself, modulo 360/Nb.
#include <gtest/gtest.h>

#include <cmath>

#include "bearing/outer_position.h"
#include "dsp/acquire.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

constexpr double kF = 409.7;  // BPFO of the 13-ball bearing of the study (Hz)
constexpr int kNb = 13;

Signal record(double theta_deg, double rate, double modulation = 0.003, double tau = 88e-6,
              double seconds = 0.3)
{
  const double fs = 1e6, level = 0.05, h = 0.45, pi = ohmdem::test::kPi, phi0 = 0.2;
  Signal in;
  in.rate = fs;
  const auto n = static_cast<std::size_t>(seconds * fs);
  in.x.resize(n);
  const double centre = phi0 + kNb * theta_deg / 360;  // the pulse's centre (cycles)
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    in.x[i] = level * (1 + modulation * std::cos(2 * pi * (kF * t - phi0)));
    // time from the pulse's centre, within (-1/2, 1/2] cycle
    const double u = std::remainder(kF * t - centre, 1.0) / kF;
    if (std::fabs(u) < tau / 2) in.x[i] += h * level;
  }
  AcquireSettings a;
  a.lowpass = 0.4 * rate;
  a.rate = rate;
  a.noise_rms = 1e-6;
  return acquire(in, a).signal;
}

double modulo_spacing(double a)
{
  const double s = 360.0 / kNb;
  return a - s * std::floor(a / s + 0.5);
}

TEST(OuterPosition, AngleModuloTheBallSpacing)
{
  for (double rate : {1e4, 2e4, 5e4}) {
    for (double theta : {0.0, 10.0, -12.0, 20.0, 45.0}) {
      const Signal r = record(theta, rate);
      const OuterPosition p = outer_position(r.x, r.rate, kF, kNb, 88e-6);
      ASSERT_TRUE(p.valid) << p.note;
      EXPECT_NEAR(p.spacing_deg, 360.0 / kNb, 1e-12);
      EXPECT_NEAR(modulo_spacing(p.angle_deg - theta), 0, 0.3) << rate << " Hz, " << theta;
      EXPECT_GE(p.angle_deg, -p.spacing_deg / 2);
      EXPECT_LT(p.angle_deg, p.spacing_deg / 2);
      // the interval holds half the crossing (88 us at 360 f / Nb deg/s: 0.50 deg)
      EXPECT_GT(p.half_width_deg, 0.5);
      EXPECT_NEAR(p.rel_modulation, 0.003, 0.0005);
      EXPECT_EQ(p.blocks, static_cast<std::size_t>(kPhaseBlocks));
    }
  }
}

TEST(OuterPosition, NoModulationOrTooShort)
{
  // no load zone (a balanced load): the fundamental is the noise's, its phase not measurable
  const Signal flat = record(10, 2e4, 0);
  const OuterPosition p = outer_position(flat.x, flat.rate, kF, kNb, 88e-6);
  EXPECT_FALSE(p.valid);
  EXPECT_NE(p.note.find("not measurable"), std::string::npos) << p.note;
  // a healthy bearing under the radial load: the modulation alone, no pulse (its crest is not
  // one: the pulse must rise kPulseOverModulation times the modulation's amplitude)
  const Signal healthy = record(10, 2e4, 0.003, 0);
  EXPECT_NE(outer_position(healthy.x, healthy.rate, kF, kNb, 88e-6).note.find("no pulse"),
            std::string::npos);
  const Signal short_record = record(10, 2e4, 0.003, 88e-6, 0.1);  // 41 passes
  EXPECT_NE(outer_position(short_record.x, short_record.rate, kF, kNb, 88e-6).note.find("too few"),
            std::string::npos);
  EXPECT_FALSE(outer_position(short_record.x, short_record.rate, 0, kNb, 88e-6).valid);
}

TEST(OuterPosition, FoldPhasesOfOneStretch)
{
  // a quarter cycle between the modulation's maximum and the pulse (theta = 90 / 13 deg)
  const Signal r = record(90.0 / kNb, 5e4);
  const FoldPhases q = fold_phases(r.x, 0, r.x.size(), r.rate, kF);
  ASSERT_TRUE(q.valid);
  const double pi = ohmdem::test::kPi;
  EXPECT_NEAR(std::remainder(q.pulse - q.modulation - pi / 2, 2 * pi), 0, 0.05);
  EXPECT_FALSE(fold_phases(std::vector<double>(5000, 1.0), 0, 5000, 5e4, kF).valid);
}

}  // namespace
}  // namespace ohmdem::post
