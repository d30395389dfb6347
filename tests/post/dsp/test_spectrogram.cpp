// SPDX-License-Identifier: GPL-2.0-or-later
// The spectrogram (post/dsp/spectrogram.h): a sine's amplitude in dB, its columns and rows.
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
