// SPDX-License-Identifier: GPL-2.0-or-later
// A race comb: pulse train or smooth modulation (bearing/pulse_train.h).
#include <gtest/gtest.h>

#include <cmath>

#include "bearing/pulse_train.h"

namespace ohmdem::post {
namespace {

FamilyScore comb(double a1, double a2, double a3)
{
  FamilyScore f;
  f.defect = "outer";
  f.label = "BPFO";
  f.harmonics = 5;
  const double a[] = {a1, a2, a3};
  for (int h = 1; h <= 3; ++h) {
    if (!(a[h - 1] > 0)) continue;  // a harmonic not found has no evidence
    Evidence e;
    e.label = std::to_string(h) + "xBPFO";
    e.amplitude = a[h - 1];
    f.evidence.push_back(e);
  }
  return f;
}

TEST(PulseTrain, HarmonicRatio)
{
  // the healthy radial 6208 at 500 rad/s and 320 N: 1.657e-5, 3.443e-6, 1.248e-6 (raw spectrum)
  EXPECT_NEAR(harmonic_ratio(comb(1.657e-5, 3.443e-6, 1.248e-6)), 0.1415, 1e-3);
  // a rectangular pulse train of duty 0.1: harmonics sinc(0.2)/sinc(0.1), sinc(0.3)/sinc(0.1)
  const auto sinc = [](double x) { return std::sin(M_PI * x) / (M_PI * x); };
  EXPECT_NEAR(harmonic_ratio(comb(sinc(0.1), sinc(0.2), sinc(0.3))),
              (sinc(0.2) + sinc(0.3)) / (2 * sinc(0.1)), 1e-12);
  EXPECT_DOUBLE_EQ(harmonic_ratio(comb(1, 0, 0.5)), 0.25);  // a missing harmonic counts 0
  EXPECT_TRUE(std::isnan(harmonic_ratio(comb(0, 1, 1))));   // no fundamental
  FamilyScore short_comb = comb(1, 1, 1);
  short_comb.harmonics = 2;  // the rate cuts the comb: too few harmonics to tell
  EXPECT_TRUE(std::isnan(harmonic_ratio(short_comb)));
}

TEST(PulseTrain, TwoDiscriminatorsTogether)
{
  const FamilyScore smooth = comb(1, 0.19, 0.1), pulses = comb(1, 0.9, 0.8);
  EXPECT_TRUE(smooth_modulation(2.71, smooth));   // the healthy radial 6208, 300 rad/s 640 N
  EXPECT_FALSE(smooth_modulation(2.98, pulses));  // a weak pulse train within 0.02 of 3
  EXPECT_FALSE(smooth_modulation(3.06, smooth));  // a pulse train by its kurtosis (sig14)
  EXPECT_FALSE(smooth_modulation(5.0, pulses));
  // a sawtooth (harmonics 1/h, kurtosis 1.8) is a modulation, not a pulse train: 0.42 < 0.5
  EXPECT_TRUE(smooth_modulation(1.8, comb(1, 0.5, 1 / 3.0)));
  // rectangular pulses of a fifth of the period: 0.67, a pulse train
  EXPECT_FALSE(smooth_modulation(2.9, comb(0.935, 0.757, 0.505)));
  FamilyScore unknown = pulses;
  unknown.harmonics = 2;  // no second discriminator: the kurtosis alone
  EXPECT_TRUE(smooth_modulation(2.98, unknown));
}

}  // namespace
}  // namespace ohmdem::post
