// SPDX-License-Identifier: GPL-2.0-or-later
// Spectrum: frequencies and amplitudes of sines (window correction, interpolation, padding,
// Welch), Parseval, and agreement with scipy.signal.welch / periodogram.
#include <gtest/gtest.h>

#include <cmath>

#include "dsp/fft.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "io/read_table.h"
#include "synth.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::reference;
using test::sine;

std::vector<double> add(std::vector<double> a, const std::vector<double> &b)
{
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
  return a;
}

TEST(Spectrum, PureSineFrequencyAndAmplitudeWithEveryWindow)
{
  const double fs = 1000, f = 123.456, A = 1.7;
  const auto x = sine(10000, fs, f, A, 0.4);
  for (WindowKind w : {WindowKind::Rectangular, WindowKind::Hann, WindowKind::Hamming,
                       WindowKind::Blackman, WindowKind::BlackmanHarris, WindowKind::Flattop}) {
    SpectrumOptions o;
    o.window = w;
    const Spectrum s = spectrum(x, fs, o);
    PeakOptions po;
    po.max_peaks = 1;
    const auto p = find_peaks(s, po);
    ASSERT_EQ(p.size(), 1u) << window_name(w);
    // the peak bin is within one bin; interpolation does much better
    EXPECT_LE(std::fabs(s.frequency(p[0].bin) - f), s.df) << window_name(w);
    EXPECT_NEAR(p[0].frequency, f, 0.01 * s.df) << window_name(w);
    EXPECT_NEAR(p[0].value, A, 0.005 * A) << window_name(w);
  }
}

TEST(Spectrum, FlattopBinAmplitudeNeedsNoInterpolation)
{
  const auto x = sine(8192, 1000, 77.77, 0.9, 1.0);
  SpectrumOptions o;
  o.window = WindowKind::Flattop;
  const Spectrum s = spectrum(x, 1000, o);
  PeakOptions po;
  po.max_peaks = 1;
  po.interpolate = false;
  const auto p = find_peaks(s, po);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].value, 0.9, 0.005 * 0.9);  // flattop scalloping loss < 0.01 dB
}

TEST(Spectrum, MixedSinesAndZeroPadding)
{
  const double fs = 2000;
  const std::size_t n = 4000;
  auto x = add(add(sine(n, fs, 50.3, 1.0, 0.1), sine(n, fs, 120.7, 0.5, 2.0)),
               sine(n, fs, 333.1, 0.25, -1.0));
  for (double &v : x) v += 3.0;  // DC, removed by detrending
  for (std::size_t pad : {1u, 4u}) {
    SpectrumOptions o;
    o.pad = pad;
    const Spectrum s = spectrum(x, fs, o);
    EXPECT_EQ(s.nfft, n * pad);
    PeakOptions po;
    po.max_peaks = 3;
    const auto p = find_peaks(s, po);
    ASSERT_EQ(p.size(), 3u);
    const double f[] = {50.3, 120.7, 333.1}, a[] = {1.0, 0.5, 0.25};
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(p[k].frequency, f[k], 0.02 * fs / n) << "pad " << pad;
      EXPECT_NEAR(p[k].value, a[k], 0.005 * a[k]) << "pad " << pad;
    }
    EXPECT_LT(s.value[0], 0.01);  // the offset of 3 is removed (what is left is leakage)
  }
}

TEST(Spectrum, WelchAveragingKeepsSineAmplitude)
{
  const double fs = 1000;
  auto x = sine(20000, fs, 61.3, 2.0, 0.0);
  test::Gaussian g(7);
  for (double &v : x) v += 0.05 * g();
  SpectrumOptions o;
  o.segment = 2048;
  o.overlap = 0.5;
  const Spectrum s = spectrum(x, fs, o);
  EXPECT_EQ(s.segments, 18u);
  PeakOptions po;
  po.max_peaks = 1;
  const auto p = find_peaks(s, po);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(p[0].frequency, 61.3, 0.05 * s.df);
  EXPECT_NEAR(p[0].value, 2.0, 0.005 * 2.0);
}

TEST(Spectrum, ParsevalRectangularPowerAndPsd)
{
  const ColumnTable t = read_table(reference("sig_gauss.txt"));
  const auto &x = t.columns[0];
  double ms = 0;
  for (double v : x) ms += v * v;
  ms /= static_cast<double>(x.size());
  SpectrumOptions o;
  o.window = WindowKind::Rectangular;
  o.detrend = Detrend::None;
  o.scaling = Scaling::Power;
  const Spectrum p = spectrum(x, 1000, o);
  double sum = 0;
  for (double v : p.value) sum += v;
  EXPECT_NEAR(sum, ms, 1e-12 * ms);
  o.scaling = Scaling::Psd;
  const Spectrum d = spectrum(x, 1000, o);
  sum = 0;
  for (double v : d.value) sum += v * d.df;
  EXPECT_NEAR(sum, ms, 1e-12 * ms);
  // odd length: no Nyquist bin
  std::vector<double> y(x.begin(), x.end() - 1);
  double ms2 = 0;
  for (double v : y) ms2 += v * v;
  ms2 /= static_cast<double>(y.size());
  o.scaling = Scaling::Power;
  sum = 0;
  for (double v : spectrum(y, 1000, o).value) sum += v;
  EXPECT_NEAR(sum, ms2, 1e-12 * ms2);
}

TEST(Spectrum, HannPsdIntegratesToVariance)
{
  test::Gaussian g(11);
  std::vector<double> x(1 << 16);
  for (double &v : x) v = 0.3 * g();
  SpectrumOptions o;
  o.scaling = Scaling::Psd;
  o.segment = 1024;
  const Spectrum s = spectrum(x, 5000, o);
  double sum = 0;
  for (double v : s.value) sum += v * s.df;
  EXPECT_NEAR(sum, 0.09, 0.02 * 0.09);
}

void expect_matches_reference(const std::string &file, const Spectrum &s)
{
  const auto rows = test::read_rows(reference(file));
  ASSERT_EQ(rows.size(), s.bins()) << file;
  double top = 0;
  for (const auto &r : rows) top = std::max(top, r[1]);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_NEAR(s.frequency(k), rows[k][0], 1e-12 * rows.back()[0]) << file << " bin " << k;
    EXPECT_NEAR(s.value[k], rows[k][1], 1e-10 * top) << file << " bin " << k;
  }
}

TEST(Spectrum, WelchMatchesScipy)
{
  for (const char *name : {"gauss", "rect_train"}) {
    const ColumnTable t = read_table(reference(std::string("sig_") + name + ".txt"));
    SpectrumOptions o;
    o.scaling = Scaling::Psd;
    o.segment = 256;
    o.overlap = 0.5;
    expect_matches_reference(std::string("welch_") + name + ".txt",
                             spectrum(t.columns[0], 1000, o));
  }
}

TEST(Spectrum, PeriodogramMatchesScipy)
{
  const ColumnTable t = read_table(reference("sig_gauss.txt"));
  SpectrumOptions o;
  o.window = WindowKind::Rectangular;
  o.detrend = Detrend::None;
  o.scaling = Scaling::Power;
  expect_matches_reference("periodogram_gauss.txt", spectrum(t.columns[0], 1000, o));
}

TEST(Spectrum, LinearDetrendRemovesRamp)
{
  std::vector<double> x(1000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 5 + 0.01 * static_cast<double>(i);
  detrend(x.data(), x.size(), Detrend::Linear);
  for (double v : x) EXPECT_NEAR(v, 0, 1e-10);
}

TEST(Spectrum, PlansAreMadeOncePerSize)
{
  const auto x = sine(3000, 1000, 10, 1, 0);
  SpectrumOptions o;
  spectrum(x, 1000, o);
  const std::size_t plans = fft_plan_count();
  for (int k = 0; k < 5; ++k) spectrum(x, 1000, o);
  EXPECT_EQ(fft_plan_count(), plans);
}

TEST(Spectrum, WindowKernelIsExactForCosineSums)
{
  // |DFT of the window| at a fractional bin, closed form against direct summation
  for (WindowKind w : {WindowKind::Hann, WindowKind::Flattop, WindowKind::Rectangular}) {
    const std::size_t n = 64, nfft = 256;
    const auto win = make_window(w, n);
    double w0 = 0;
    for (double v : win) w0 += v;
    for (double u : {0.0, 0.3, 1.7, 4.5}) {
      std::complex<double> sum = 0;
      for (std::size_t j = 0; j < n; ++j)
        sum += win[j] * std::polar(1.0, -2 * 3.14159265358979323846 * u * static_cast<double>(j) /
                                            static_cast<double>(nfft));
      EXPECT_NEAR(window_kernel(w, n, nfft, u), std::abs(sum) / std::fabs(w0), 1e-12)
          << window_name(w) << " u=" << u;
    }
  }
}

}  // namespace
}  // namespace ohmdem::post
