// SPDX-License-Identifier: GPL-2.0-or-later
// Kinematic frequencies against the values of the paper (SKF 6208) and the bearing data
// center's published fault-frequency multiples (SKF 6205 drive end).
#include <gtest/gtest.h>

#include <cmath>

#include "bearing/bearing.h"
#include "core/error.h"

namespace ohmdem::post {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Frequencies, Skf6208At500RadPerSecond)
{
  const DefectFrequencies f = defect_frequencies(bearing_preset("6208"), 500 / (2 * kPi));
  EXPECT_NEAR(f.fr, 79.58, 0.005);
  EXPECT_NEAR(f.ftf, 31.52, 0.005);
  EXPECT_NEAR(f.bpfo, 409.7, 0.05);
  EXPECT_NEAR(f.bpfi, 624.8, 0.05);
  EXPECT_NEAR(f.bsf, 183.1, 0.05);
  // identities of the formulas
  EXPECT_NEAR(f.bpfo + f.bpfi, 13 * f.fr, 1e-9);
  EXPECT_NEAR(f.bpfo, 13 * f.ftf, 1e-9);
}

TEST(Frequencies, Skf6205MultiplesOfShaftSpeed)
{
  // CWRU bearing data center: inner 5.4152, outer 3.5848, cage 0.39828, rolling element
  // 4.7135 (= 2 BSF) times the shaft frequency
  const DefectFrequencies f = defect_frequencies(bearing_preset("6205"), 1.0);
  EXPECT_NEAR(f.bpfi, 5.4152, 1e-4);
  EXPECT_NEAR(f.bpfo, 3.5848, 1e-4);
  EXPECT_NEAR(f.ftf, 0.39828, 5e-5);  // the published value is 3e-5 low
  EXPECT_NEAR(2 * f.bsf, 4.7135, 1e-4);
}

TEST(Frequencies, ContactAngleEntersThroughCosine)
{
  BearingGeometry g = bearing_preset("6208");
  g.contact_angle_deg = 60;  // cos = 1/2: same as a ball half as large
  BearingGeometry h = bearing_preset("6208");
  h.db /= 2;
  const auto a = defect_frequencies(g, 10), b = defect_frequencies(h, 10);
  EXPECT_NEAR(a.ftf, b.ftf, 1e-12);
  EXPECT_NEAR(a.bpfi, b.bpfi, 1e-12);
}

TEST(Frequencies, RejectsBadGeometry)
{
  BearingGeometry g = bearing_preset("6208");
  g.dp = g.db / 2;
  EXPECT_THROW(defect_frequencies(g, 10), Error);
  EXPECT_THROW(defect_frequencies(bearing_preset("6208"), 0), Error);
  EXPECT_THROW(bearing_preset("6209"), Error);
}

}  // namespace
}  // namespace ohmdem::post
