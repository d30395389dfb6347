// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post diagnose --across-column`: an outer defect's angle from the load
// direction from a two-axis accelerometer record, end to end, and its bad input. The record is
// synthetic: at every outer-race pass (BPFO = Nb/2 fr (1 - d/D), the kinematic frequency) a
// decaying ring along 30 deg from the first axis, with independent noise on each axis.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "cli_run.h"
#include "io/json.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;
using test::CliRun;
using test::run;

// Nb 9, d 7.94 mm, D 39.04 mm at 1800 rpm: BPFO = 4.5 x 30 x (1 - 7.94 / 39.04) Hz.
const std::string kBearing = " --nb 9 --db 7.94e-3 --dp 39.04e-3 --rpm 1800";
constexpr double kBpfo = 4.5 * 30 * (1 - 7.94 / 39.04), kRate = 20000, kAngle = 30;

std::string two_axis_record()
{
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::string text = "# time V V2\n";
  const double th = kAngle * kPi / 180;
  for (int i = 0; i < 2 * static_cast<int>(kRate); ++i) {
    const double t = i / kRate, s = std::fmod(t * kBpfo + 0.5, 1.0) / kBpfo;
    const double ring = std::exp(-s / 3e-4) * std::sin(2 * kPi * 3000 * s);
    text += std::to_string(t) + " " + std::to_string(std::cos(th) * ring + noise(rng)) + " " +
            std::to_string(std::sin(th) * ring + noise(rng)) + "\n";
  }
  return text;
}

TEST(Cli, AcrossColumnPlacesAnOuterDefectFromTheLoadDirection)
{
  const std::string file = test::write_temp("across_two_axes.txt", two_axis_record());
  const std::string in = "diagnose " + file + kBearing +
                         " --column V --across-column V2 --size-method accel-curve "
                         "--assume-defect outer --load radial --format json";
  CliRun r = run(in);
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out.substr(r.out.find('{')), "across");
  const Json *pos = j.find("position_deg");
  ASSERT_TRUE(pos && pos->is_number()) << r.out;
  EXPECT_NEAR(pos->number(), kAngle, 1.0);
  const Json *iv = j.find("position_interval_deg");
  ASSERT_TRUE(iv && iv->is_array()) << r.out;
  EXPECT_LT((*iv)[0].number(), kAngle);
  EXPECT_GT((*iv)[1].number(), kAngle);
  EXPECT_EQ(j.find("position_reference")->string(), "load direction");
  // the text report names the reference, and the second axis among the inputs
  r = run("diagnose " + file + kBearing +
          " --column V --across-column V2 --size-method double-impulse --assume-defect outer "
          "--load radial");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("] from the load direction"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("second axis"), std::string::npos) << r.out;
  // a balanced load has no load direction to measure from
  r = run("diagnose " + file + kBearing +
          " --column V --across-column V2 --size-method accel-curve --assume-defect outer "
          "--load fixed");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("only a radial load has"), std::string::npos) << r.out;
}

TEST(Cli, AcrossColumnBadInput)
{
  const std::string file = test::write_temp("across_bad_input.txt", two_axis_record());
  const std::string in = "diagnose " + file + kBearing + " --column V ";
  CliRun r = run(in + "--across-column V --size-method accel-curve");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--across-column V holds the record's own samples: name the sensor's "
                       "second axis"),
            std::string::npos)
      << r.out;
  // the second axis is the passes place method's, whatever sizes the record
  r = run(in + "--across-column V2 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(Json::parse(r.out, "diagnose output").find("place_method_name")->string(), "passes");
  r = run(in + "--across-column W --size-method accel-curve");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("W"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace ohmdem::post
