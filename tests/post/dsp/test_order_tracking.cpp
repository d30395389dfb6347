// SPDX-License-Identifier: GPL-2.0-or-later
// Order tracking: resampling at constant shaft angle against a run-up with a known phase (the
// record of tests/post/make_order_reference.py), its order spectrum against scipy on the same
// angle-domain data, the anti-alias filter, and the angle from a speed column.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "dsp/order_tracking.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;
constexpr double kFs = 2000, kS = 32;

// fr(t) = 10 + 10 t Hz: theta(t) = 2 pi (10 t + 5 t^2), 40 revolutions in 2 s
double theta_of(double t)
{
  return 2 * kPi * (10 * t + 5 * t * t);
}
double omega_of(double t)
{
  return 2 * kPi * (10 + 10 * t);
}
double shaft_part(double phi)
{
  return std::cos(5.3 * phi) + 0.4 * std::cos(11.2 * phi + 0.5);
}

struct Record {
  std::vector<double> t, theta, omega, x;
};

Record run_up()
{
  Record r;
  for (int i = 0; i < 4000; ++i) {
    const double t = i / kFs;
    r.t.push_back(t);
    r.theta.push_back(theta_of(t));
    r.omega.push_back(omega_of(t));
    // + a tone fixed at 900 Hz, above the angle domain's Nyquist order (16 orders = 160..480 Hz)
    r.x.push_back(shaft_part(theta_of(t)) + 0.3 * std::cos(2 * kPi * 900 * t));
  }
  return r;
}

// Samples of revolutions 2..38 (k = 64..1215 counted from theta = 0), as in the reference.
std::vector<double> revolutions_2_to_38(const AngleResampled &r)
{
  const double k0 = r.theta0 / (2 * kPi / r.samples_per_rev);
  const long first = 2 * static_cast<long>(kS) - std::lround(k0);
  EXPECT_NEAR(k0, std::round(k0), 1e-9);  // the grid is anchored at theta[0] = 0
  EXPECT_GE(first, 0);
  EXPECT_LE(static_cast<std::size_t>(first) + 36 * 32, r.x.size());
  return {r.x.begin() + first, r.x.begin() + first + 36 * 32};
}

TEST(Orders, ResampledRunUpMatchesTheKnownPhase)
{
  const Record rec = run_up();
  const AngleResampled r = resample_by_angle(rec.x, kFs, rec.theta, kS);
  EXPECT_DOUBLE_EQ(r.samples_per_rev, kS);
  EXPECT_NEAR(r.flat_order, 12.8, 1e-12);
  double worst = 0;
  for (std::size_t k = 0; k < r.x.size(); ++k) {
    const double phi = r.theta0 + static_cast<double>(k) * 2 * kPi / kS;
    worst = std::max(worst, std::fabs(r.x[k] - shaft_part(phi)));
  }
  // Kaiser passband ripple ~1e-5 and the 900 Hz tone >= 100 dB down (0.3 -> 3e-6); the linear
  // angle interpolation between samples is exact to alpha dt^2 / 8 = 2e-6 rad here
  EXPECT_LT(worst, 1e-4) << "largest deviation from cos(5.3 phi) + 0.4 cos(11.2 phi + 0.5)";
  std::printf("[ orders     ] %zu angle samples, largest deviation from the exact phase %.3g\n",
              r.x.size(), worst);
  // the first sample lies where the kernel (16 zero crossings) fits into the record
  EXPECT_GT(r.t0, 0);
  EXPECT_LT(r.t0, 0.2);
  EXPECT_GT(r.revolutions(), 37);
}

TEST(Orders, OrderSpectrumMatchesScipyOnTheSameAngleData)
{
  const Record rec = run_up();
  const std::vector<double> y = revolutions_2_to_38(resample_by_angle(rec.x, kFs, rec.theta, kS));
  SpectrumOptions o;  // Hann, mean removed, amplitude: the "rate" is samples per revolution
  const Spectrum sp = spectrum(y, kS, o);
  const auto ref = test::read_rows(test::reference("orders_chirp.txt"));
  ASSERT_EQ(ref.size(), sp.bins());
  for (std::size_t k = 0; k < sp.bins(); ++k) {
    ASSERT_NEAR(sp.frequency(k), ref[k][0], 1e-12);
    EXPECT_NEAR(sp.value[k], ref[k][1], 2e-4) << "order " << ref[k][0];
  }
  // the lines at orders 5.3 and 11.2, interpolated, within 0.1 % (design: 0.01 bin)
  PeakOptions po;
  po.max_peaks = 2;
  const auto peaks = find_peaks(sp, po);
  ASSERT_EQ(peaks.size(), 2u);
  EXPECT_NEAR(peaks[0].frequency, 5.3, 5.3e-3);
  EXPECT_NEAR(peaks[0].value, 1.0, 0.01);
  EXPECT_NEAR(peaks[1].frequency, 11.2, 11.2e-3);
  EXPECT_NEAR(peaks[1].value, 0.4, 0.004);
  std::printf("[ orders     ] order lines %.6f (5.3) and %.6f (11.2)\n", peaks[0].frequency,
              peaks[1].frequency);
}

TEST(Orders, WithoutResamplingTheRunUpSmearsTheLine)
{
  // the reason for order tracking: in the time domain the 5.3 order sweeps 53..159 Hz
  const Record rec = run_up();
  SpectrumOptions o;
  const Spectrum sp = spectrum(rec.x, kFs, o);
  double top = 0;
  for (double v : sp.value) top = std::max(top, v);
  EXPECT_LT(top, 0.35);  // versus 1.0 for the tracked line
}

TEST(Orders, ConstantSpeedAngleTurnsOnceEveryPeriod)
{
  // 12.5 rev/s at 1 kHz: one revolution (2 pi) every 80 samples
  const std::vector<double> theta = constant_speed_angle(801, 1000, 12.5);
  ASSERT_EQ(theta.size(), 801u);
  EXPECT_EQ(theta[0], 0);
  EXPECT_NEAR(theta[80], 2 * kPi, 1e-12);
  EXPECT_NEAR(theta[800], 20 * kPi, 1e-11);
}

TEST(Orders, AngleFromSpeedIsTheTrapezoidIntegral)
{
  const Record rec = run_up();
  // a linear speed is integrated exactly by the trapezoid rule
  const auto th = angle_from_speed(rec.omega, kFs);
  for (std::size_t i = 0; i < th.size(); ++i) ASSERT_NEAR(th[i], rec.theta[i], 1e-9);
  // rpm and Hz columns give the same angle
  EXPECT_NEAR(to_rad_per_s(600, SpeedUnit::Rpm), 2 * kPi * 10, 1e-12);
  EXPECT_NEAR(to_rad_per_s(10, SpeedUnit::Hz), 2 * kPi * 10, 1e-12);
  EXPECT_EQ(parse_speed_unit("RPM"), SpeedUnit::Rpm);
  EXPECT_THROW(parse_speed_unit("deg/s"), Error);
  // a quadratic angle (linear speed): scipy.integrate.cumulative_trapezoid is exact too; a
  // sinusoidal speed 2 pi (20 + 5 sin(2 pi t)): error h^2/12 max|omega''| T = 5e-7 rad
  std::vector<double> w;
  for (int i = 0; i < 4000; ++i) w.push_back(2 * kPi * (20 + 5 * std::sin(2 * kPi * i / kFs)));
  const auto th2 = angle_from_speed(w, kFs);
  const double T = 3999 / kFs;
  const double exact = 2 * kPi * (20 * T + 5 * (1 - std::cos(2 * kPi * T)) / (2 * kPi));
  EXPECT_NEAR(th2.back(), exact, 1e-6);
}

TEST(Orders, SpeedSummaryMeasuresTheVariation)
{
  const Record rec = run_up();
  const SpeedSummary s = speed_summary(rec.theta, kFs);
  EXPECT_NEAR(s.mean, 2 * kPi * (10 + 5 * 3999 / kFs), 1e-9);  // mean over 0..1.9995 s
  // block speeds from 10.6 to 29.4 Hz (16 blocks of 1/8 s): (29.375 - 10.625) / 20
  EXPECT_NEAR(s.variation, 0.9375, 1e-3);
  std::vector<double> steady(1000);
  for (std::size_t i = 0; i < steady.size(); ++i) steady[i] = 3.0 * static_cast<double>(i) / kFs;
  EXPECT_NEAR(speed_summary(steady, kFs).variation, 0, 1e-9);
}

TEST(Orders, RejectsAngleThatDoesNotIncrease)
{
  Record rec = run_up();
  rec.theta[100] = rec.theta[99];
  try {
    resample_by_angle(rec.x, kFs, rec.theta, kS);
    FAIL() << "no error";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("must increase strictly"), std::string::npos) << e.what();
  }
  EXPECT_THROW(resample_by_angle(rec.x, kFs, std::vector<double>(10, 0.0), kS), Error);
  EXPECT_THROW(resample_by_angle(run_up().x, kFs, run_up().theta, 2), Error);
}

}  // namespace
}  // namespace ohmdem::post
