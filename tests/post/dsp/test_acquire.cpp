// SPDX-License-Identifier: GPL-2.0-or-later
// The measurement chain of `acquire` (post/dsp/acquire.h): the ADC against the theory of uniform
// quantization, the noise against its density, aliasing against the filter's response, the
// interpolation against its error bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "dsp/acquire.h"
#include "dsp/butterworth.h"
#include "dsp/spectrum.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

Signal make_signal(std::vector<double> x, double rate, double t0 = 0)
{
  Signal s;
  s.x = std::move(x);
  s.rate = rate;
  s.t0 = t0;
  s.name = "x";
  return s;
}

std::vector<double> tone(std::size_t n, double fs, double f, double a, double phase = 0.3)
{
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = a * std::sin(2 * kPi * f * i / fs + phase);
  return x;
}

// Amplitude of the tone at f in y[i0..] (sampled at fs) by least squares on cos, sin and a
// constant: exact for a pure tone whatever the number of periods.
double tone_amplitude(const std::vector<double> &y, double fs, double f, std::size_t i0)
{
  double m[3][4] = {};
  for (std::size_t i = i0; i < y.size(); ++i) {
    const double ph = 2 * kPi * f * i / fs;
    const double b[3] = {std::cos(ph), std::sin(ph), 1};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += b[r] * b[c];
      m[r][3] += b[r] * y[i];
    }
  }
  for (int p = 0; p < 3; ++p)  // Gauss-Jordan; the matrix is symmetric positive definite
    for (int r = 0; r < 3; ++r) {
      if (r == p) continue;
      const double k = m[r][p] / m[p][p];
      for (int c = 0; c < 4; ++c) m[r][c] -= k * m[p][c];
    }
  return std::hypot(m[0][3] / m[0][0], m[1][3] / m[1][1]);
}

double rms(const std::vector<double> &x)
{
  double s = 0;
  for (double v : x) s += v * v;
  return std::sqrt(s / x.size());
}

// --- Butterworth design and filtering

TEST(Adc, QuantizationErrorRmsIsStepOverSqrt12)
{
  // uniform quantization of a busy signal (many incommensurate tones and noise, spanning
  // hundreds of steps): the error is uniform on [-q/2, q/2], rms q/sqrt(12)
  const std::size_t n = 100000;
  GaussianNoise g(7);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = 0.5 * std::sin(0.0123 * i) + 0.3 * std::sin(0.377 * i + 1) + 0.05 * g.next();
  for (int bits : {8, 12, 16}) {
    std::vector<double> y = x;
    EXPECT_EQ(quantize(y, bits, -1, 1), 0u);
    const double q = 2 / std::ldexp(1.0, bits);
    std::vector<double> e(n);
    double emax = 0;
    for (std::size_t i = 0; i < n; ++i) {
      e[i] = y[i] - x[i];
      emax = std::max(emax, std::abs(e[i]));
    }
    const double ratio = rms(e) / (q / std::sqrt(12.0));
    std::printf("[ measured ] %d bits: quantization error rms / (q/sqrt 12) = %.4f\n", bits, ratio);
    // standard error of the rms of n uniform errors: 1/sqrt(5 n) ~ 0.0014 relative; 2 % bound
    EXPECT_NEAR(ratio, 1, 0.02) << bits;
    EXPECT_LE(emax, q / 2 * (1 + 1e-9)) << bits;
  }
}

TEST(Adc, MidTreadRoundingOfExactValues)
{
  // 3 bits on [-1, 1]: q = 0.25, levels -1, -0.75, ..., 0.75 (0 is a level: mid-tread)
  std::vector<double> x = {0, 0.25, -1, 0.75, 0.1, 0.124, 0.125, -0.125, 0.87, 0.875, 1, -1.2, 5};
  const std::vector<double> want = {0, 0.25, -1, 0.75, 0, 0, 0.25, 0, 0.75, 0.75, 0.75, -1, 0.75};
  // 0.125 and -0.125 are ties: up; 0.875 = HI - q/2 is the tie above the top level, rounds up
  // to the missing code 8 and is clipped to 0.75, as are 1, -1.2 and 5
  EXPECT_EQ(quantize(x, 3, -1, 1), 4u);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(x[i], want[i]) << i;
  // one bit on [0, 2]: levels 0 and 1
  std::vector<double> y = {0.49, 0.5, 1.49, 1.51};
  EXPECT_EQ(quantize(y, 1, 0, 2), 1u);
  EXPECT_EQ(y, (std::vector<double>{0, 1, 1, 1}));
}

TEST(Adc, ClippedCountOfAnOverdrivenSine)
{
  // a sine of amplitude A on [-1, 1]: clipped above HI - q/2 and below LO - q/2, which a sine
  // at an irrational frequency exceeds for the fraction acos(threshold/A)/pi of the time
  const std::size_t n = 200000;
  const double a = 1.5, q = 2 / 256.0;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = a * std::sin(std::sqrt(2.0) * i);
  const double expected = n * (std::acos((1 - q / 2) / a) + std::acos((1 + q / 2) / a)) / kPi;
  const std::size_t clipped = quantize(x, 8, -1, 1);
  EXPECT_NEAR(static_cast<double>(clipped), expected, 0.002 * n);
  EXPECT_EQ(*std::max_element(x.begin(), x.end()), 1 - q);
  EXPECT_EQ(*std::min_element(x.begin(), x.end()), -1);
}

// --- noise

TEST(Noise, GaussianMomentsAndDeterminism)
{
  const std::size_t n = 400000;
  GaussianNoise g(42), h(42), other(43);
  double s1 = 0, s2 = 0, s4 = 0;
  bool differs = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = g.next();
    ASSERT_EQ(v, h.next());
    differs = differs || v != other.next();
    s1 += v, s2 += v * v, s4 += v * v * v * v;
  }
  EXPECT_TRUE(differs);
  // bounds: 5 standard errors of the mean (1/sqrt n), variance (sqrt(2/n)), kurtosis
  // (sqrt(24/n)) of n standard normal deviates
  EXPECT_NEAR(s1 / n, 0, 5 / std::sqrt(n));
  EXPECT_NEAR(s2 / n, 1, 5 * std::sqrt(2.0 / n));
  EXPECT_NEAR(s4 / n / std::pow(s2 / n, 2), 3, 5 * std::sqrt(24.0 / n));
}

TEST(Noise, DensityGivesRmsOverTheOutputNyquistBand)
{
  // a zero signal at 200 kHz sampled at 50 kHz with density D: rms = D sqrt(25000 Hz)
  const double d = 3e-6;
  AcquireSettings s;
  s.rate = 50000;
  s.lowpass = 20000;
  s.noise_density = d;
  const Acquisition a = acquire(make_signal(std::vector<double>(800000, 0.0), 200000), s);
  ASSERT_EQ(a.signal.size(), 200000u);
  const double expected = d * std::sqrt(25000.0);
  EXPECT_DOUBLE_EQ(a.noise_sigma, expected);
  const double ratio = rms(a.signal.x) / expected;
  std::printf("[ measured ] noise rms / (density sqrt(rate/2)) = %.5f over %zu samples\n", ratio,
              a.signal.size());
  // the rms of n normal deviates has a relative standard error 1/sqrt(2n) = 0.0016: 1 % is 6
  EXPECT_NEAR(ratio, 1, 0.01);
  // a given rms is the rms per sample whatever the rate
  s.noise_density = 0;
  s.noise_rms = 0.25;
  const Acquisition b = acquire(make_signal(std::vector<double>(800000, 0.0), 200000), s);
  EXPECT_NEAR(rms(b.signal.x) / 0.25, 1, 0.01);
}

TEST(Noise, DensityIsTheOneSidedPsdLevel)
{
  // the Welch PSD (Hann, 1024-sample segments, one-sided) of the added noise is flat at D^2:
  // --noise-density is the density a spectrum analyser would read
  const double d = 2e-8;
  AcquireSettings s;
  s.noise_density = d;
  const Acquisition a = acquire(make_signal(std::vector<double>(200000, 0.0), 50000), s);
  SpectrumOptions o;
  o.scaling = Scaling::Psd;
  o.segment = 1024;
  const Spectrum p = spectrum(a.signal.x, 50000, o);
  double mean = 0;
  for (std::size_t k = 1; k + 1 < p.bins(); ++k) mean += p.value[k];  // DC and Nyquist left out
  mean /= static_cast<double>(p.bins() - 2);
  std::printf("[ measured ] Welch PSD level / density^2 = %.4f\n", mean / (d * d));
  // 511 bins x 389 half-overlapping segments: relative standard error well below 1 %
  EXPECT_NEAR(mean / (d * d), 1, 0.02);
}

TEST(Noise, SameSeedSameRecord)
{
  AcquireSettings s;
  s.noise_rms = 0.1;
  s.seed = 5;
  const Signal in = make_signal(tone(1000, 1e4, 130, 1), 1e4);
  const auto a = acquire(in, s), b = acquire(in, s);
  EXPECT_EQ(a.signal.x, b.signal.x);
  s.seed = 6;
  EXPECT_NE(acquire(in, s).signal.x, a.signal.x);
}

// --- sampling

TEST(Sampling, IntegerRatioTakesEveryKthFilteredSample)
{
  const std::vector<double> x = test::read_column(test::reference("acquire_input.txt"));
  AcquireSettings s;
  s.lowpass = 20000;
  s.rate = 50000;
  const Acquisition a = acquire(make_signal(x, 1e6, 0.125), s);
  EXPECT_EQ(a.decimation, 20u);
  const Sos sos = butterworth_lowpass(4, 20000, 1e6);
  std::vector<double> y = x;
  SosState st = sos_steady_state(sos, x[0]);
  sos_filter(sos, y, st);
  ASSERT_EQ(a.signal.size(), (x.size() + 19) / 20);
  for (std::size_t i = 0; i < a.signal.size(); ++i) EXPECT_EQ(a.signal.x[i], y[20 * i]) << i;
  EXPECT_EQ(a.signal.t0, 0.125);  // the input's clock
  EXPECT_EQ(a.signal.rate, 50000);
  EXPECT_TRUE(a.warnings.empty());
}

TEST(Sampling, IntegerRatioToleratesAFittedInputRate)
{
  EXPECT_EQ(integer_ratio(1e6, 50000), 20u);
  EXPECT_EQ(integer_ratio(1e6 * (1 - 3e-13), 50000), 20u);  // a rate fitted to printed stamps
  EXPECT_EQ(integer_ratio(1e6, 1e6), 1u);
  EXPECT_EQ(integer_ratio(1e6, 48000), 0u);
  EXPECT_EQ(integer_ratio(1e6, 50001), 0u);  // 19.9996: 2e-5 off, interpolated
  EXPECT_EQ(integer_ratio(1e6, 1e-300), 0u);
}

TEST(Sampling, SteadyStartHasNoTransientZeroStartHasTheStepResponse)
{
  // a constant R of 1.39 ohm: from a steady state the filter outputs it unchanged, from rest it
  // rises from b0 * 1.39 (the step response), as scipy's sosfilt without zi
  AcquireSettings s;
  s.lowpass = 20000;
  s.order = 6;
  const Signal in = make_signal(std::vector<double>(2000, 1.39), 1e6);
  const Acquisition a = acquire(in, s);
  for (double v : a.signal.x) ASSERT_NEAR(v, 1.39, 1e-12);
  s.steady_start = false;
  const Acquisition b = acquire(in, s);
  EXPECT_NEAR(b.signal.x[0], b.filter[0].b0 * 1.39, 1e-18);
  EXPECT_LT(b.signal.x[10], 0.1);
  EXPECT_NEAR(b.signal.x.back(), 1.39, 1e-6);
}

TEST(Sampling, NoOptionIsACopy)
{
  const std::vector<double> x = test::read_column(test::reference("acquire_input.txt"));
  const Acquisition a = acquire(make_signal(x, 1e6, 0.5), AcquireSettings{});
  EXPECT_EQ(a.signal.x, x);
  EXPECT_EQ(a.signal.rate, 1e6);
  EXPECT_EQ(a.signal.t0, 0.5);
  EXPECT_TRUE(a.filter.empty());
}

TEST(Sampling, CubicInterpolationWithinItsErrorBound)
{
  // a 20 kHz tone at 1 MHz read at rates that do not divide it: the error is at most
  // (3/128)(2 pi f/fs)^4 of the amplitude inside the record, (1/24)(2 pi f/fs)^4 in the first and
  // last input interval (where the stencil cannot be centred)
  const double fs = 1e6, f = 20000, amp = 1.3;
  const std::vector<double> x = tone(20000, fs, f, amp);
  const double bound = cubic_interpolation_error(f, fs);
  const double end_bound = std::pow(2 * kPi * f / fs, 4) / 24;
  for (double rate : {48000.0, 44100.0, 37000.0, 51234.5}) {
    AcquireSettings s;
    s.rate = rate;
    const Acquisition a = acquire(make_signal(x, fs), s);
    EXPECT_EQ(a.decimation, 0u);
    ASSERT_EQ(a.warnings.size(), 1u);  // no --lowpass: aliasing warning
    EXPECT_EQ(a.signal.size(), static_cast<std::size_t>(std::floor(19999 * rate / fs)) + 1);
    double inner = 0, ends = 0;
    for (std::size_t j = 0; j < a.signal.size(); ++j) {
      const double u = j * fs / rate;  // position in input samples
      const double e = std::abs(a.signal.x[j] - amp * std::sin(2 * kPi * f * (u / fs) + 0.3)) / amp;
      (u < 1 || u > 19998 ? ends : inner) = std::max(u < 1 || u > 19998 ? ends : inner, e);
    }
    std::printf(
        "[ measured ] interpolation at %g Hz: max error %.3g of the amplitude (bound %.3g)\n", rate,
        inner, bound);
    EXPECT_LE(inner, bound * 1.001 + 1e-14) << rate;
    EXPECT_GT(inner, bound / 4) << rate;  // the bound is tight: a worse scheme would fail
    EXPECT_LE(ends, end_bound * 1.001 + 1e-14) << rate;
  }
}

TEST(Sampling, ToneAboveNyquistIsAttenuatedByTheFilter)
{
  // 37 kHz sampled at 25 kHz aliases to 12 kHz; the anti-alias filter (order 4, 10 kHz)
  // leaves |H(37 kHz)| of it, from the closed-form Butterworth magnitude
  const double fs = 1e6, f = 37000, amp = 2;
  const Signal in = make_signal(tone(200000, fs, f, amp), fs);
  for (double rate : {25000.0, 24000.0}) {  // decimation by 40; interpolation
    AcquireSettings s;
    s.lowpass = 10000;
    s.rate = rate;
    const Acquisition a = acquire(in, s);
    const double alias = f - rate;
    // skip the first 2 ms: the filter's start-up transient on the tone
    const double got =
        tone_amplitude(a.signal.x, rate, alias, static_cast<std::size_t>(0.002 * rate));
    const double theory = amp * butterworth_gain(4, 10000, fs, f);
    std::printf(
        "[ measured ] %g Hz at %g Hz: alias at %g Hz, amplitude / theory = %.6f "
        "(|H| = %.4g)\n",
        f, rate, alias, got / theory, theory / amp);
    // interpolation scales a tone by at most cubic_interpolation_error(f) (6e-5 here)
    EXPECT_NEAR(got / theory, 1, 1e-4) << rate;
    // without the filter the alias keeps the full amplitude
    s.lowpass = 0;
    const Acquisition b = acquire(in, s);
    EXPECT_NEAR(tone_amplitude(b.signal.x, rate, alias, 0) / amp, 1, 1e-4) << rate;
  }
}

// --- the chain and its checks

TEST(Acquire, ScaleOffsetThenAdc)
{
  // R around 1.39 ohm times 10 mA plus 1 mV, 12 bits on [0, 0.02] V
  AcquireSettings s;
  s.scale = 0.01;
  s.offset = 0.001;
  s.bits = 12;
  s.lo = 0;
  s.hi = 0.02;
  const std::vector<double> x = {1.39, 1.40, 1.5054, 2.5, 1.39};
  const Acquisition a = acquire(make_signal(x, 1000), s);
  const double q = 0.02 / 4096;
  EXPECT_DOUBLE_EQ(a.q, q);
  EXPECT_EQ(a.clipped, 1u);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("1 of 5 samples (20 %) clipped"), std::string::npos)
      << a.warnings[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = std::min(0.01 * x[i] + 0.001, 0.02 - q);
    EXPECT_NEAR(a.signal.x[i], v, q / 2 * (1 + 1e-9)) << i;
    EXPECT_NEAR(a.signal.x[i] / q, std::round(a.signal.x[i] / q), 1e-6) << i;  // on a level
  }
}

TEST(Acquire, RejectsImpossibleSettings)
{
  const Signal in = make_signal(tone(1000, 1e4, 100, 1), 1e4);
  auto fails = [&](AcquireSettings s, const std::string &what) {
    try {
      acquire(in, s);
      ADD_FAILURE() << "no error for " << what;
    } catch (const Error &e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  AcquireSettings s;
  s.rate = 2e4;
  fails(s, "exceeds the input's sampling rate");
  s = {};
  s.lowpass = 5000;
  fails(s, "at or above the input's Nyquist");
  s.rate = 5000;
  s.lowpass = 2500;
  fails(s, "at or above the output Nyquist");
  s = {};
  s.lowpass = 100;
  s.order = 0;
  fails(s, "option order expects");
  s.order = 21;
  fails(s, "option order expects");
  s = {};
  s.bits = 33;
  s.lo = 0, s.hi = 1;
  fails(s, "option bits expects 1..32");
  s.bits = 8;
  s.hi = 0;
  fails(s, "empty ADC range");
  s = {};
  s.noise_rms = 1, s.noise_density = 1;
  fails(s, "give the noise once");
  s = {};
  s.noise_rms = -1;
  fails(s, "option noise_rms expects a value >= 0");
  s = {};
  s.scale = 0;
  fails(s, "option scale");
  s = {};
  s.rate = 1;
  fails(s, "leaves 1 sample");
  Signal bad = in;
  bad.x[500] = NAN;
  try {
    acquire(bad, AcquireSettings{});
    ADD_FAILURE() << "NaN accepted";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find("non-finite value at sample 500"), std::string::npos);
  }
  EXPECT_THROW(acquire(make_signal({1, 2, 3}, 10), AcquireSettings{}), Error);
}

}  // namespace
}  // namespace ohmdem::post
