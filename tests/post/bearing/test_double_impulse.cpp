// SPDX-License-Identifier: GPL-2.0-or-later
// The double-impulse size (post/bearing/double_impulse.h) on synthetic accelerometer records: a
// ring resonance (a damped oscillator) driven by a ball's force at every defect pass, dropping
// over 30 us as the ball enters (the step) and coming back at the exit with a 10 us overshoot
// to 3 times the load (the impulse), simulated at 1 MHz and acquired at 20 and 50 kHz through
// the Butterworth anti-alias filter of dsp/acquire, with white noise. The reference is the
// delay the record was made with.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "bearing/double_impulse.h"
#include "dsp/acquire.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

// Passes at f (Hz), entry-exit delay tau; resonance fn (Hz), damping ratio zeta.
Signal record(double tau, double f, double rate, double noise = 1e-3, double fn = 6000,
              double zeta = 0.05)
{
  const double fs = 1e6, dt = 1 / fs, w = 2 * kPi * fn;
  const std::size_t n = 300000;
  Signal in;
  in.rate = fs;
  in.x.assign(n, 0.0);
  double u = 0, v = 0;  // the oscillator's displacement and velocity; the record is its accel.
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    const double s = std::fmod(t * f + 0.3, 1.0) / f;  // time since the pass's entry
    double force = 1;
    if (s < tau) force = 1 - std::min(1.0, s / 30e-6);  // the ball unloads as it enters
    if (s >= tau && s < tau + 10e-6) force = 3;         // the exit: reloaded with an overshoot
    const double a = w * w * (force - u) - 2 * zeta * w * v;
    v += a * dt;
    u += v * dt;
    in.x[i] = a / (w * w);
  }
  AcquireSettings acq;
  acq.lowpass = 0.4 * rate;
  acq.rate = rate;
  acq.noise_rms = noise;
  return acquire(in, acq).signal;
}

TEST(DoubleImpulse, DelayOfEntryAndExitAtEveryRate)
{
  const double f = 409.7;
  const int nb = 13;
  for (double rate : {2e4, 5e4})
    for (double tau : {200e-6, 500e-6}) {
      const Signal r = record(tau, f, rate);
      const DoubleImpulseSize e = size_from_double_impulse(r.x, r.rate, f, "outer", nb, {});
      ASSERT_TRUE(e.valid) << rate << " Hz, tau " << tau << ": " << e.note;
      // within a sample (the peak's parabola on a sampled autocorrelation) and 5 %
      EXPECT_NEAR(e.delay_s, tau, 1 / rate + 0.05 * tau) << rate << " Hz, tau " << tau;
      EXPECT_LE(e.delay_lo_s, tau + 1 / rate);
      EXPECT_GE(e.delay_hi_s, tau - 1 / rate);
      // size = delay x the ball's speed relative to the ring: 2 pi f tau / Nb (deg here)
      EXPECT_NEAR(e.size_deg, 360 * f * e.delay_s / nb, 1e-12);
      EXPECT_GT(e.passes, 100U);
    }
}

TEST(DoubleImpulse, DelayUnderTwoSamplesIsNotDetermined)
{
  const Signal r = record(60e-6, 409.7, 2e4);  // 1.2 samples at 20 kHz
  const DoubleImpulseSize e = size_from_double_impulse(r.x, r.rate, 409.7, "outer", 13, {});
  EXPECT_FALSE(e.valid);
  EXPECT_NE(e.note.find("not determined"), std::string::npos) << e.note;
}

TEST(DoubleImpulse, PureNoiseIsNotSized)
{
  std::mt19937 g(3);
  std::normal_distribution<double> n(0, 1);
  std::vector<double> x(20000);
  for (double &v : x) v = n(g);
  const DoubleImpulseSize e = size_from_double_impulse(x, 2e4, 409.7, "outer", 13, {});
  EXPECT_FALSE(e.valid) << e.note;
}

TEST(DoubleImpulse, BallDefectAndBadSettingsAreRefused)
{
  const Signal r = record(200e-6, 409.7, 2e4);
  EXPECT_FALSE(size_from_double_impulse(r.x, r.rate, 409.7, "ball", 13, {}).valid);
  DoubleImpulseSettings s;
  s.groups = 2;
  EXPECT_THROW(size_from_double_impulse(r.x, r.rate, 409.7, "outer", 13, s), std::invalid_argument);
}

}  // namespace
}  // namespace ohmdem::post
