// SPDX-License-Identifier: GPL-2.0-or-later
// Envelope: agreement with scipy.signal.hilbert, an AM carrier, an impulse train through a
// resonance (with the kurtogram choosing the band), spectral kurtosis of noise.
#include <gtest/gtest.h>

#include <cmath>

#include "dsp/envelope.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "io/read_table.h"
#include "synth.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

constexpr double kPi = 3.14159265358979323846;
using test::reference;

TEST(Envelope, FullBandEqualsScipyHilbert)
{
  for (const char *name : {"gauss", "impulses"}) {  // even and odd lengths
    const ColumnTable t = read_table(reference(std::string("sig_") + name + ".txt"));
    const auto want = test::read_column(reference(std::string("hilbert_") + name + ".txt"));
    const auto env = envelope(t.columns[0], 1000, {0, 0});
    ASSERT_EQ(env.size(), want.size());
    double top = 0;
    for (double v : want) top = std::max(top, v);
    for (std::size_t i = 0; i < env.size(); ++i)
      ASSERT_NEAR(env[i], want[i], 1e-12 * top) << name << " sample " << i;
  }
}

Peak top_peak(const std::vector<double> &x, double fs, double fmax)
{
  SpectrumOptions o;
  const Spectrum s = spectrum(x, fs, o);
  PeakOptions po;
  po.max_peaks = 1;
  po.fmax = fmax;
  const auto p = find_peaks(s, po);
  return p.empty() ? Peak{} : p[0];
}

TEST(Envelope, AmplitudeModulatedCarrierGivesModulationFrequency)
{
  const double fs = 20000, fm = 37.0, fc = 2000, m = 0.5;
  std::vector<double> x(20000);
  test::Gaussian g(3);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / fs;
    x[i] = (1 + m * std::cos(2 * kPi * fm * t)) * std::sin(2 * kPi * fc * t) + 0.01 * g();
  }
  const auto env = envelope(x, fs, {1500, 2500});
  const Peak p = top_peak(env, fs, 1000);
  EXPECT_NEAR(p.frequency, fm, 0.05);
  EXPECT_NEAR(p.value, m, 0.01 * m);  // the envelope is 1 + m cos: amplitude m at fm
}

// Impulses every 1/frep exciting a damped resonance at fres, buried in noise.
std::vector<double> impulse_train(double fs, double frep, double fres, std::size_t n, double noise)
{
  std::vector<double> x(n, 0.0);
  test::Gaussian g(5);
  const double zeta = 0.02, wn = 2 * kPi * fres;
  for (double t0 = 0.013; t0 < static_cast<double>(n) / fs; t0 += 1 / frep) {
    const auto i0 = static_cast<std::size_t>(std::ceil(t0 * fs));
    for (std::size_t i = i0; i < n && i < i0 + static_cast<std::size_t>(0.01 * fs); ++i) {
      const double t = static_cast<double>(i) / fs - t0;
      x[i] += std::exp(-zeta * wn * t) * std::sin(wn * std::sqrt(1 - zeta * zeta) * t);
    }
  }
  // low-frequency interference that a whole-band envelope would follow
  for (std::size_t i = 0; i < n; ++i)
    x[i] += noise * g() + 2.0 * std::sin(2 * kPi * 29.95 * static_cast<double>(i) / fs);
  return x;
}

TEST(Envelope, ImpulseTrainThroughResonanceGivesRepetitionFrequency)
{
  const double fs = 12000, frep = 107.3, fres = 3500;
  const auto x = impulse_train(fs, frep, fres, 60000, 0.3);
  const Kurtogram kg = kurtogram(x, fs, 6, 500);
  EXPECT_LE(kg.best.lo, fres);
  EXPECT_GE(kg.best.hi, fres);
  EXPECT_GT(kg.best.kurtosis, 0.5);
  const auto env = envelope(x, fs, {kg.best.lo, kg.best.hi});
  const Peak p = top_peak(env, fs, 1000);
  EXPECT_NEAR(p.frequency, frep, 0.2);
}

TEST(Envelope, SpectralKurtosisOfGaussianNoiseIsNearZero)
{
  test::Gaussian g(9);
  std::vector<double> x(1 << 16);
  for (double &v : x) v = g();
  const Kurtogram kg = kurtogram(x, 10000, 4, 0);
  for (const auto &c : kg.cells) EXPECT_NEAR(c.kurtosis, 0.0, 0.2) << c.lo << "-" << c.hi;
}

}  // namespace
}  // namespace ohmdem::post
