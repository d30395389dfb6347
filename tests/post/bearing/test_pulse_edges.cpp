// SPDX-License-Identifier: GPL-2.0-or-later
// The pulses' entry-to-exit width (post/bearing/pulse_edges.h) on synthetic records:
// rectangular jumps lasting tau through the instrument chain of dsp/acquire (Butterworth
// anti-alias filter at 0.4 x rate, then sampling). Both edges go through the same linear
// filter, so the width is tau plus a constant of the chain: the reference is the difference
// of the widths of two pulse lengths, which must equal the difference of the lengths.
#include <gtest/gtest.h>

#include <cmath>

#include "bearing/pulse_edges.h"
#include "pulse_records.h"

namespace ohmdem::post {
namespace {

Signal record(double tau, double f, double rate, double decay = 0)
{
  return test_records::pulse_record(tau, f, rate, 0, 0, decay);
}

TEST(PulseEdges, WidthGrowsAsThePulseAtResolvedLengths)
{
  // resolved: the pulse lasts 2 samples or more (the diagnosis's switch)
  for (double rate : {2e4, 5e4}) {
    const double t1 = 2.5 / rate, t2 = 5 / rate;
    for (double decay : {0.0, 40e-6}) {
      const Signal a = record(t1, 409.7, rate, decay), b = record(t2, 409.7, rate, decay);
      const PulseEdges ea = pulse_edge_width(a.x, a.rate, 409.7);
      const PulseEdges eb = pulse_edge_width(b.x, b.rate, 409.7);
      ASSERT_TRUE(ea.valid && eb.valid) << ea.note << eb.note;
      EXPECT_NEAR((eb.width_s - ea.width_s) / (t2 - t1), 1, 0.05) << rate << " Hz, decay " << decay;
      EXPECT_LT(ea.se_s, 0.05 * ea.width_s);
      EXPECT_EQ(ea.blocks, static_cast<std::size_t>(kEdgeBlocks));
    }
  }
}

TEST(PulseEdges, TooFewPassesOrNoPulse)
{
  const Signal r = record(200e-6, 409.7, 2e4);
  std::vector<double> few(r.x.begin(), r.x.begin() + 1000);  // 0.05 s: 20 passes
  EXPECT_FALSE(pulse_edge_width(few, r.rate, 409.7).valid);
  const std::vector<double> flat(6000, 1.0);
  EXPECT_FALSE(pulse_edge_width(flat, 2e4, 409.7).valid);
}

TEST(PulseEdges, ReadOnTheCurve)
{
  const std::vector<double> sizes{1, 2, 3}, widths{100e-6, 150e-6, 250e-6};
  const CurveReading r = read_on_curve(sizes, widths, 125e-6, 10e-6);
  EXPECT_DOUBLE_EQ(r.size, 1.5);
  EXPECT_NEAR(r.lo, 1.3, 1e-12);
  EXPECT_NEAR(r.hi, 1.7, 1e-12);
  // below the curve's first point the lower end goes toward the origin in proportion
  EXPECT_NEAR(read_on_curve(sizes, widths, 105e-6, 10e-6).lo, 0.95, 1e-12);
  // past its last point: no upper end
  EXPECT_TRUE(std::isnan(read_on_curve(sizes, widths, 245e-6, 10e-6).hi));
  EXPECT_TRUE(std::isnan(read_on_curve(sizes, widths, 260e-6, 10e-6).size));
}

}  // namespace
}  // namespace ohmdem::post
