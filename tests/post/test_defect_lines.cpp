// SPDX-License-Identifier: GPL-2.0-or-later
// The table of a bearing's kinematic lines and what is computed from it: peak labels, the
// kurtogram's band width, fault bands (checked against Parseval on a sine on a bin) and the
// spectrogram (a sine's amplitude in dB, its columns and rows).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bearing/defect_lines.h"
#include "bearing/fault_bands.h"
#include "core/error.h"
#include "dsp/spectrogram.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Round numbers, so each line is easy to place by hand.
DefectFrequencies lines()
{
  DefectFrequencies k;
  k.fr = 10;
  k.ftf = 4;
  k.bpfo = 36;
  k.bpfi = 54;
  k.bsf = 23;
  return k;
}

TEST(DefectLines, TableOrderKeysAndValues)
{
  std::vector<std::string> keys, fault;
  std::vector<double> f;
  for (const DefectLine &l : defect_lines()) {
    keys.push_back(l.key);
    f.push_back(l.of(lines()));
    if (l.fault_line) fault.push_back(l.name);
  }
  EXPECT_EQ(keys, (std::vector<std::string>{"fr", "ftf", "bpfo", "bpfi", "bsf", "two_bsf"}));
  EXPECT_EQ(f, (std::vector<double>{10, 4, 36, 54, 23, 46}));
  EXPECT_EQ(fault, (std::vector<std::string>{"FTF", "BPFO", "BPFI", "2BSF"}));
  std::set<std::string> families;
  for (const DefectLine &l : defect_lines()) families.insert(l.defect);
  EXPECT_EQ(families, (std::set<std::string>{"", "inner", "outer", "ball", "cage"}));
}

TEST(DefectLines, LabelsTheNearestHarmonicWithinTolerance)
{
  const DefectFrequencies k = lines();
  EXPECT_EQ(label_frequency(2 * 36 * 1.01, k, 5, 0.02), "2xBPFO");
  EXPECT_EQ(label_frequency(54, k, 5, 0.02), "1xBPFI");
  EXPECT_EQ(label_frequency(2 * 36 * 1.03, k, 5, 0.02), "");  // outside 2 %
  EXPECT_EQ(label_frequency(6 * 36, k, 5, 0.02), "4xBPFI");   // 216 = 4 x 54; 6 x BPFO > N
  EXPECT_EQ(label_frequency(6 * 36, k, 6, 0.02), "4xBPFI");   // tie with 6xBPFO: the later line
  EXPECT_EQ(label_frequency(2, k, 5, 0.02), "");
  EXPECT_EQ(harmonic_label(1, defect_lines()[2], false), "BPFO");
  EXPECT_EQ(harmonic_label(2, defect_lines()[5], false), "2x2BSF");
}

TEST(DefectLines, KurtogramBandCarriesTheHarmonicsOfTheFastestLine)
{
  const DefectFrequencies k = lines();
  EXPECT_DOUBLE_EQ(highest_defect_frequency(k), 54);  // BPFI > 2 BSF = 46 > BPFO
  EXPECT_DOUBLE_EQ(defect_band_width(k, 5, 10000), 1.1 * 5 * 54);
  EXPECT_DOUBLE_EQ(defect_band_width(k, 5, 1000), 250);  // at most a quarter of the rate
  DefectFrequencies ball = k;
  ball.bsf = 40;  // 2 BSF = 80 is now the fastest
  EXPECT_DOUBLE_EQ(highest_defect_frequency(ball), 80);
}

TEST(FaultBands, SineOnABinGivesItsAmplitudeAndPower)
{
  // 2 s at 1 kHz: bins every 0.5 Hz; a sine of amplitude 0.3 at BPFI = 54 Hz (a bin). Hann,
  // amplitude scaling: the peak reads 0.3; Parseval over the line's 3 bins (0.5, 1, 0.5 of the
  // peak, ENBW 1.5 bins) gives the power A^2/2 = 0.045.
  const double rate = 1000, a = 0.3;
  std::vector<double> x(2000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = a * std::sin(2 * kPi * 54 * i / rate);
  const Spectrum s = spectrum(x, rate, SpectrumOptions{});
  const std::vector<FaultBand> bands = fault_bands(s, lines(), 2, 0.02);
  const FaultBand *bpfi = nullptr, *bpfo = nullptr;
  for (const auto &b : bands) {
    if (b.label == "1xBPFI") bpfi = &b;
    if (b.label == "1xBPFO") bpfo = &b;
  }
  ASSERT_NE(bpfi, nullptr);
  EXPECT_NEAR(bpfi->center, 54, 1e-12);
  EXPECT_NEAR(bpfi->lo, 54 * 0.98, 1e-12);
  EXPECT_NEAR(bpfi->hi, 54 * 1.02, 1e-12);
  EXPECT_NEAR(bpfi->peak_amplitude, a, 1e-9);
  EXPECT_NEAR(bpfi->peak_frequency, 54, 1e-9);
  EXPECT_NEAR(bpfi->power, a * a / 2, 1e-9);
  ASSERT_NE(bpfo, nullptr);  // far from the sine: leakage only
  EXPECT_LT(bpfo->power, 1e-20);
  // 2 harmonics of 6 lines, none reaching fs/2 = 500 Hz: 12 bands in table order
  ASSERT_EQ(bands.size(), 12u);
  EXPECT_EQ(bands.front().label, "1xfr");
  EXPECT_EQ(bands.back().label, "2x2BSF");
}

TEST(FaultBands, BandsReachingNyquistAreLeftOut)
{
  std::vector<double> x(200, 0.0);
  x[3] = 1;
  const Spectrum s = spectrum(x, 100, SpectrumOptions{});  // fs/2 = 50 Hz
  for (const auto &b : fault_bands(s, lines(), 3, 0.02)) EXPECT_LT(b.hi, 50) << b.label;
}

TEST(Spectrogram, SineReadsItsAmplitudeInEveryColumn)
{
  // 8192 samples at 1024 Hz, segments of 256 (4 Hz bins), a sine of amplitude 2 at 64 Hz (a
  // bin): 20 log10(2) = 6.0206 dB in the row of 64 Hz, every column
  Signal s;
  s.rate = 1024;
  s.t0 = 1;
  s.x.resize(8192);
  for (std::size_t i = 0; i < s.x.size(); ++i) s.x[i] = 2 * std::sin(2 * kPi * 64 * i / s.rate);
  SpectrogramOptions o;
  o.segment = 256;
  o.fmin = 0;
  o.fmax = 200;
  const Spectrogram sg = spectrogram(s, o);
  EXPECT_EQ(sg.segment, 256u);
  EXPECT_EQ(sg.hop, 64u);                         // a quarter segment
  EXPECT_EQ(sg.t.size(), (8192 - 256) / 64 + 1);  // 125 columns, below 400
  EXPECT_DOUBLE_EQ(sg.df, 4);
  EXPECT_DOUBLE_EQ(sg.t.front(), 1 + 128.0 / 1024);  // centre of the first segment
  ASSERT_EQ(sg.f.size(), 51u);                       // bins 0..200 Hz, one row each
  const std::size_t row = 16;                        // 64 Hz
  EXPECT_DOUBLE_EQ(sg.f[row], 64);
  for (std::size_t c = 0; c < sg.t.size(); ++c)
    EXPECT_NEAR(sg.db[row * sg.t.size() + c], 20 * std::log10(2.0), 1e-9);
  // the floor: nothing below the peak minus 100 dB
  for (double v : sg.db) EXPECT_GE(v, 20 * std::log10(2.0) - 100 - 1e-9);
  // a constant speed of 5 rev/s reads 5 Hz in every segment
  std::vector<double> theta(s.size());
  for (std::size_t i = 0; i < theta.size(); ++i) theta[i] = 2 * kPi * 5 * i / s.rate;
  for (double f : segment_shaft_hz(sg, theta, s.rate)) EXPECT_NEAR(f, 5, 1e-9);
}

TEST(Spectrogram, NoBinInTheRangeIsAnError)
{
  Signal s;
  s.rate = 1000;
  s.x.assign(1000, 1.0);
  SpectrogramOptions o;
  o.fmin = 600;
  o.fmax = 700;
  EXPECT_THROW(spectrogram(s, o), Error);
}

}  // namespace
}  // namespace ohmdem::post
