// SPDX-License-Identifier: GPL-2.0-or-later
// Two channels: impulses heard on both sensors belong to the channel where they are
// the more impulsive (bearing/other_channel.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bearing/order_diagnose.h"
#include "bearing/other_channel.h"
#include "core/error.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

constexpr double kRate = 12000;

// A pulse train at f_pulse Hz, each pulse ringing 3 kHz (damping 5 %), 4 s.
std::vector<double> pulse_train(double f_pulse)
{
  const std::size_t n = static_cast<std::size_t>(4 * kRate);
  std::vector<double> x(n, 0.0);
  const double fn = 3000, zeta = 0.05, w = 2 * ohmdem::test::kPi * fn;
  for (double t0 = 0.001; t0 < 4; t0 += 1 / f_pulse) {
    const auto i0 = static_cast<std::size_t>(t0 * kRate);
    for (std::size_t j = 0; j < 200 && i0 + j < n; ++j) {
      const double t = static_cast<double>(j) / kRate;
      x[i0 + j] += std::exp(-zeta * w * t) * std::sin(w * t);
    }
  }
  return x;
}

std::vector<double> plus_noise(std::vector<double> x, double gain, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, sigma);
  for (double &v : x) v = gain * v + g(rng);
  return x;
}

TEST(OtherChannel, TransmittedImpulsesBelongToTheMoreImpulsiveChannel)
{
  // the source's sensor: the train over a little noise; the far sensor: a tenth of it (20 dB of
  // housing attenuation) under its own noise
  const std::vector<double> train = pulse_train(107);
  const std::vector<double> near = plus_noise(train, 1, 0.02, 1);
  const std::vector<double> far = plus_noise(train, 0.1, 0.05, 2);
  const Band band{2000, 4000};
  const ChannelComparison at_far = compare_channels(far, near, kRate, band, 10, 1000);
  EXPECT_FALSE(at_far.lines_hz.empty());
  EXPECT_GT(at_far.coherence, 0.5) << at_far.describe();
  EXPECT_GT(at_far.other_excess, 2 * at_far.this_excess) << at_far.describe();
  EXPECT_TRUE(at_far.transmitted()) << at_far.describe();
  // seen from the source's channel, the other is the less impulsive: its own impulses
  const ChannelComparison at_near = compare_channels(near, far, kRate, band, 10, 1000);
  EXPECT_FALSE(at_near.transmitted()) << at_near.describe();
}

TEST(OtherChannel, IndependentImpulsesAreNotTransmitted)
{
  // each sensor's own train (two defects at 107 and 131 Hz): the envelopes share no line
  const std::vector<double> a = plus_noise(pulse_train(107), 0.2, 0.05, 3);
  const std::vector<double> b = plus_noise(pulse_train(131), 1, 0.02, 4);
  const ChannelComparison c = compare_channels(a, b, kRate, {2000, 4000}, 10, 1000);
  EXPECT_LT(c.coherence, 0.5) << c.describe();
  EXPECT_FALSE(c.transmitted()) << c.describe();
}

TEST(OtherChannel, OnlyAFlaggedRecordChanges)
{
  ChannelComparison c;
  c.lines_hz = {107};
  c.coherence = 0.9;
  c.this_excess = 0.5;
  c.other_excess = 10;
  ASSERT_TRUE(c.transmitted());
  Diagnosis named;
  named.defect = "outer";
  attribute_to_other_channel(named, c, 0.3);
  EXPECT_EQ(named.defect, "outer");  // a named family is this bearing's evidence: kept
  Diagnosis flagged;
  flagged.defect = "unidentified";
  attribute_to_other_channel(flagged, c, 0.3);
  EXPECT_EQ(flagged.defect, "none");
  EXPECT_EQ(flagged.candidate, "other channel");
  EXPECT_NE(flagged.reason.find("impulses from the other channel"), std::string::npos);
}

TEST(OtherChannel, RefusesChannelsOfDifferentLengths)
{
  const std::vector<double> a(4096, 0.0), b(4000, 0.0);
  EXPECT_THROW(compare_channels(a, b, kRate, {2000, 4000}, 10, 1000), SettingError);
}

TEST(OtherChannel, RefusedInTheAngleDomain)
{
  // the other sensor would have to be resampled at the same shaft angles: refused by name
  Signal s;
  s.rate = kRate;
  s.x.assign(4096, 0.0);
  std::vector<double> theta(s.x.size());
  for (std::size_t i = 0; i < theta.size(); ++i) theta[i] = 0.01 * static_cast<double>(i);
  DiagnoseOptions o;
  o.other_channel = &s;
  try {
    diagnose_in_orders(s, theta, o);
    ADD_FAILURE() << "no error";
  } catch (const SettingError &e) {
    EXPECT_NE(std::string(e.what()).find("other_channel is not supported when the speed varies"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ohmdem::post
