// SPDX-License-Identifier: GPL-2.0-or-later
// Fault bands (post/bearing/fault_bands.h), checked against Parseval on a sine on a bin.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bearing/defect_lines.h"
#include "bearing/fault_bands.h"
#include "core/error.h"
#include "dsp/spectrogram.h"
#include "dsp/spectrum.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

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

}  // namespace
}  // namespace ohmdem::post
