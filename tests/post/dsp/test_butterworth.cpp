// SPDX-License-Identifier: GPL-2.0-or-later
// The Butterworth design and filtering (post/dsp/butterworth.h) against scipy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.h"
#include "dsp/acquire.h"
#include "dsp/butterworth.h"
#include "dsp/spectrum.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

// --- Butterworth design and filtering

TEST(Butterworth, SectionsMatchScipyButter)
{
  // reference/butter_sos.txt: scipy.signal.butter(N, fc, fs=fs, output='sos') from
  // make_acquire_reference.py, 14 orders (1..20) x 10 cut-offs (0.0005 to 0.49 fs) x 2 rates
  const auto rows = test::read_rows(test::reference("butter_sos.txt"));
  ASSERT_GT(rows.size(), 1000u);
  double worst = 0;
  std::size_t i = 0, filters = 0;
  while (i < rows.size()) {
    const int n = static_cast<int>(rows[i][0]);
    const double fc = rows[i][1], fs = rows[i][2];
    const Sos sos = butterworth_lowpass(n, fc, fs);
    ASSERT_EQ(sos.size(), static_cast<std::size_t>((n + 1) / 2)) << "N " << n;
    for (std::size_t s = 0; s < sos.size(); ++s, ++i) {
      const auto &r = rows.at(i);
      ASSERT_EQ(r[3], static_cast<double>(s));
      ASSERT_EQ(r[7], 1.0);
      const double mine[5] = {sos[s].b0, sos[s].b1, sos[s].b2, sos[s].a1, sos[s].a2};
      const double ref[5] = {r[4], r[5], r[6], r[8], r[9]};
      // the first section carries the gain, down to 1e-50 for N = 20: relative comparison
      const double scale = std::max({std::abs(ref[0]), std::abs(ref[1]), std::abs(ref[2])});
      for (int c = 0; c < 5; ++c) {
        const double err = std::abs(mine[c] - ref[c]) / (c < 3 ? scale : 1.0);
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-9) << "N " << n << " fc " << fc << " fs " << fs << " section " << s
                             << " coefficient " << c;
      }
    }
    ++filters;
  }
  std::printf("[ measured ] %zu filters: largest coefficient difference from scipy %.3g\n", filters,
              worst);
}

TEST(Butterworth, FilteringMatchesScipySosfilt)
{
  // reference/acquire_sosfilt.txt: scipy.signal.sosfilt of acquire_input.txt (zero state, and
  // zi = sosfilt_zi(sos) * x[0]) for the CASES of make_acquire_reference.py
  const std::vector<double> x = test::read_column(test::reference("acquire_input.txt"));
  const auto ref = test::read_rows(test::reference("acquire_sosfilt.txt"));
  ASSERT_EQ(ref.size(), x.size());
  const std::pair<int, double> cases[] = {{4, 20000}, {5, 100000}, {8, 150000}, {1, 3000}};
  double worst = 0;
  for (std::size_t c = 0; c < 4; ++c) {
    const Sos sos = butterworth_lowpass(cases[c].first, cases[c].second, 1e6);
    for (int steady = 0; steady < 2; ++steady) {
      std::vector<double> y = x;
      SosState st = steady ? sos_steady_state(sos, x[0]) : sos_zero_state(sos);
      sos_filter(sos, y, st);
      double err = 0;
      for (std::size_t i = 0; i < y.size(); ++i)
        err = std::max(err, std::abs(y[i] - ref[i].at(2 * c + steady)));
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-9) << "N " << cases[c].first << " fc " << cases[c].second
                           << (steady ? " steady" : " zero");
    }
  }
  std::printf("[ measured ] sosfilt: largest difference from scipy %.3g (signal ~1.4)\n", worst);
}

TEST(Butterworth, ResponseIsTheBilinearButterworthMagnitude)
{
  // closed form |H| = 1/sqrt(1 + (tan(pi f/fs)/tan(pi fc/fs))^2N): independent of the design
  for (int n : {1, 2, 3, 4, 7, 8, 12}) {
    const double fs = 1e6, fc = 20000;
    const Sos sos = butterworth_lowpass(n, fc, fs);
    EXPECT_NEAR(std::abs(sos_response(sos, fc, fs)), 1 / std::sqrt(2.0), 1e-12) << n;
    EXPECT_NEAR(std::abs(sos_response(sos, 0, fs)), 1, 1e-12) << n;
    for (double f : {1000.0, 15000.0, 25000.0, 37000.0, 80000.0, 300000.0}) {
      const double h = std::abs(sos_response(sos, f, fs)), g = butterworth_gain(n, fc, fs, f);
      EXPECT_NEAR(h, g, 1e-9 * g + 1e-15) << "N " << n << " f " << f;
    }
  }
}

TEST(Butterworth, DelayAtZeroHertzIsTheAnalogPrototypes)
{
  // the analog Butterworth's group delay at 0 Hz: sum_k sin((2k - 1) pi / 2N) / (2 pi fc) (its
  // poles -sin + i cos on the unit circle, each adding Re(-p)/|p|^2); the bilinear transform
  // keeps it where fc << fs. And against the phase's slope of sos_response near 0 Hz.
  for (int n : {1, 2, 4, 7}) {
    const double fs = 1e6, fc = 4000;
    double analog = 0;
    for (int k = 1; k <= n; ++k) analog += std::sin((2 * k - 1) * kPi / (2 * n));
    analog /= 2 * kPi * fc;
    const Sos sos = butterworth_lowpass(n, fc, fs);
    const double d = sos_dc_delay_s(sos, fs);
    EXPECT_NEAR(d, analog, 1e-4 * analog) << n;
    const double df = 0.01;  // Hz
    const double slope = -std::arg(sos_response(sos, df, fs)) / (2 * kPi * df);
    EXPECT_NEAR(d, slope, 1e-7 * d) << n;
  }
}

// The group delay at f against scipy.signal.group_delay of each section of
// scipy.signal.butter(N, fc, fs=1e6, output='sos'), summed (scipy 1.10, Debian's python3-scipy):
// the order-4 4 kHz filter of a 10 kHz record and the order-7 20 kHz one; at 0 Hz it is the
// delay at 0 Hz.
TEST(Butterworth, GroupDelayAgainstScipy)
{
  const double fs = 1e6;
  const Sos four = butterworth_lowpass(4, 4000, fs);
  const std::pair<double, double> four_ref[] = {{1000, 0.00010685177390092403},
                                                {2000, 0.00011858967636329114},
                                                {3000, 0.00014574264489428294},
                                                {4000, 0.0001470554753115868},
                                                {8000, 2.9654482428729856e-05}};
  for (const auto &[f, ref] : four_ref)
    EXPECT_NEAR(sos_group_delay_s(four, f, fs), ref, 1e-9 * ref) << f;
  EXPECT_NEAR(sos_group_delay_s(four, 0, fs), sos_dc_delay_s(four, fs), 1e-15);
  const Sos seven = butterworth_lowpass(7, 20000, fs);
  EXPECT_NEAR(sos_group_delay_s(seven, 10000, fs), 3.965947501497795e-05, 1e-14);
  EXPECT_NEAR(sos_group_delay_s(seven, 20000, fs), 6.149806179910561e-05, 1e-14);
}

TEST(Butterworth, RejectsImpossibleDesigns)
{
  EXPECT_THROW(butterworth_lowpass(0, 100, 1000), Error);
  EXPECT_THROW(butterworth_lowpass(21, 100, 1000), Error);
  EXPECT_THROW(butterworth_lowpass(2, 500, 1000), Error);
  EXPECT_THROW(butterworth_lowpass(2, 0, 1000), Error);
  EXPECT_THROW(butterworth_lowpass(2, 100, 0), Error);
}

// --- ADC

}  // namespace
}  // namespace ohmdem::post
