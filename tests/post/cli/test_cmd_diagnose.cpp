// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post diagnose` end to end: our run layout (signal.txt + run.json), its formats (the
// measured records: validation/test_real_records_diagnose.cpp).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::make_run_dir;
using test::run;
using test::shell;

TEST(Cli, DiagnoseOurRunFromItsMetadata)
{
  for (const char *kind : {"inner", "outer"}) {
    const std::string dir = make_run_dir(std::string("run_") + kind, kind);
    const CliRun r = run("diagnose " + dir + "/signal.txt --format json");
    ASSERT_EQ(r.status, 0) << r.out;
    const Json j = Json::parse(r.out, "diagnose output");
    for (const char *key : {"defect", "score", "frequency_hz", "evidence"})
      EXPECT_TRUE(j.find(key)) << key;
    EXPECT_EQ(j.find("defect")->string(), kind);
    EXPECT_EQ(j.find("run_defect")->string(), kind);
    EXPECT_TRUE(j.find("evidence")->is_array());
    EXPECT_GT(j.find("evidence")->size(), 0u);
    const Json *size = j.find("size_deg");
    ASSERT_TRUE(size && size->is_number()) << r.out;
    EXPECT_NEAR(size->number(), 1.0, 0.05);
    // the sliding phase (t < 5 ms) was skipped as run.json says
    EXPECT_NE(j.find("meta")->find("sliding phase skipped"), nullptr);
  }
}

// the size with its interval from the pulse area, in every format. The synthetic run
// (run.json: load force, 13 balls) holds rectangles of 1/12 of the level lasting a 1 deg
// crossing: the theory's jump 1/(Nb-1), so the area gives 1 deg.
TEST(Cli, DiagnoseSizeIntervalAndPosition)
{
  for (const char *kind : {"inner", "outer"}) {
    const std::string dir = make_run_dir(std::string("run_area_") + kind, kind);
    const CliRun r = run("diagnose " + dir + "/signal.txt --format json");
    ASSERT_EQ(r.status, 0) << r.out;
    const Json j = Json::parse(r.out, "diagnose output");
    ASSERT_TRUE(j.find("size_deg") && j.find("size_deg")->is_number()) << r.out;
    EXPECT_NEAR(j.find("size_deg")->number(), 1.0, 0.03) << kind;
    // the theory's pass-to-pass interval was never measured to cover a size: none is given
    EXPECT_TRUE(j.find("size_interval_deg")->is_null()) << kind;
    EXPECT_NE(j.find("size_method")->string().find("no interval"), std::string::npos);
    EXPECT_EQ(j.find("size_method_name")->string(), "area");
    // a balanced load: every pass looks the same, the position is not determined
    EXPECT_TRUE(j.find("position_deg")->is_null());
    EXPECT_TRUE(j.find("position_interval_deg")->is_null());
    EXPECT_TRUE(j.find("position_reference")->is_null());
    EXPECT_NE(j.find("position_note")->string().find("not determined"), std::string::npos);
    EXPECT_NE(j.find("depth")->string().find("not determined"), std::string::npos);
  }
  const std::string dir = make_run_dir("run_area_table", "inner");
  const CliRun t = run("diagnose " + dir + "/signal.txt");
  EXPECT_NE(t.out.find("size:          "), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("by area"), std::string::npos) << t.out;
  const CliRun csv = run("diagnose " + dir + "/signal.txt --format csv");
  EXPECT_NE(csv.out.find(",size_area_deg,size_low_deg,size_high_deg,position_deg,"),
            std::string::npos);
  // a radial load needs the model's jump: the flag is named, nothing is guessed
  const CliRun radial = run("diagnose " + dir + "/signal.txt --load radial --format json");
  const Json jr = Json::parse(radial.out, "diagnose output");
  EXPECT_NE(jr.find("size_method")->string().find("--pulse-height"), std::string::npos);
  EXPECT_TRUE(jr.find("size_interval_deg")->is_null());
  const CliRun bad = run("diagnose " + dir + "/signal.txt --load sideways 2>&1");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("--load must be force, fixed or radial"), std::string::npos);
}

// Without the model's curve the area rests on the theory's flat jump: a pulse half that high
// (an area giving 0.5 deg where the width gives 1 deg, as the deck's 5 um pits with their exit
// dip give) is not sized by the theory: the size is the width's, with no interval, and the
// curve is named instead of a wrong area size.
TEST(Cli, DiagnoseRefusesTheTheorysSizeWhenThePulseIsNotItsJump)
{
  const std::string dir = make_run_dir("run_area_half_jump", "inner");
  std::ifstream in(dir + "/signal.txt");
  std::ostringstream out;
  std::string line;
  std::getline(in, line);
  out << line << "\n";
  const double level = test::DefectSpec{}.level;  // the synthetic run's level (synth.h)
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double t, w, fi, fo, n, r, m;
    ls >> t >> w >> fi >> fo >> n >> r >> m;
    if (t >= 0.005 && r > level) r = level + (r - level) / 2;
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", t, w, fi, fo, n, r, m);
    out << buf;
  }
  in.close();
  std::ofstream(dir + "/signal.txt") << out.str();
  const CliRun r = run("diagnose " + dir + "/signal.txt --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out, "diagnose output");
  EXPECT_EQ(j.find("defect")->string(), "inner");
  // not determined: no width-size printed in its stead (one answer)
  EXPECT_TRUE(j.find("size_deg")->is_null()) << r.out;
  EXPECT_EQ(j.find("size_status")->string(), "not determined");
  EXPECT_TRUE(j.find("size_interval_deg")->is_null());
  const std::string method = j.find("size_method")->string();
  EXPECT_NE(method.find("not the flat jump"), std::string::npos) << method;
  EXPECT_NE(method.find("--size-curve"), std::string::npos) << method;
}

// Size and place on held-out simulated records (tests/post/data/sizing: the sizing study's runs of the
// 6208 at 500 rad/s, 50 um pits, acquired at 20 kHz, 16 bits, low noise, first 0.15 s; not used
// to build the estimator). The reference is the size and place the deck was given; the bounds
// are the errors doc/methods/size_pulse_area.md reports, so a change that degrades them fails here.
TEST(Cli, DiagnoseSizesHeldOutSimulatedRecords)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  auto diagnose = [&](const std::string &name, const std::string &extra) {
    const CliRun r = run("diagnose " + data + name + "_20kHz.txt --column V --metadata " + data +
                         name + ".json --format json " + extra);
    EXPECT_EQ(r.status, 0) << r.out;
    return Json::parse(r.out, "diagnose output");
  };
  // fixed load, 3 deg inner: the theory's jump 1/(Nb-1)
  const Json fixed = diagnose("inner_3_fixed_p90", "");
  EXPECT_EQ(fixed.find("defect")->string(), "inner");
  EXPECT_NEAR(fixed.find("size_deg")->number(), 3.0, 0.15);
  // the same read off the model's curve (the study's first curve_inner_fixed.txt: 1 MHz runs of
  // the scene at 0.2, 0.4, 0.7, 1.5, 2.5, 4 deg)
  const Json curve =
      diagnose("inner_3_fixed_p90", "--size-curve " + data + "curve_inner_fixed.txt");
  EXPECT_NEAR(curve.find("size_deg")->number(), 3.0, 0.06);
  EXPECT_NE(curve.find("pulse_height_source")->string().find("--size-curve"), std::string::npos);
  // with the curve's own error (5 %, relative SD of its area) the interval holds +-1.96 x 5 % of
  // the area around it: the curve is nearly proportional there, so about +-0.3 deg
  const Json wide =
      diagnose("inner_3_fixed_p90",
               "--size-curve " + data + "curve_inner_fixed.txt --size-model-error 0.05");
  const Json &iv = *wide.find("size_interval_deg");
  EXPECT_NEAR(iv[0].number(), 3.0 - 0.29, 0.1);
  EXPECT_NEAR(iv[1].number(), 3.0 + 0.29, 0.1);
  const CliRun alone =
      run("diagnose " + data + "inner_3_fixed_p90_20kHz.txt --column V --metadata " + data +
          "inner_3_fixed_p90.json --size-model-error 0.05");
  EXPECT_NE(alone.status, 0);
  EXPECT_NE(alone.out.find("--size-model-error needs --size-curve"), std::string::npos)
      << alone.out;
  // radial load, 0.5 deg inner pit at 330 deg on the ring: the jump from the calibration run,
  // the place from the shaft angle column
  const Json inner =
      diagnose("inner_0.5_radial_p330", "--assume-defect inner --pulse-height 0.4494");
  EXPECT_NEAR(inner.find("size_deg")->number(), 0.5, 0.075);
  EXPECT_NEAR(inner.find("position_deg")->number(), 330, 3);
  EXPECT_EQ(inner.find("position_reference")->string(), "shaft zero");
  const Json &inner_iv = *inner.find("position_interval_deg");
  EXPECT_LE(inner_iv[0].number(), 330);
  EXPECT_GE(inner_iv[1].number(), 330);
  // the same record on a curve its area lies beyond: no size, the place all the same (the load
  // zone gives it, whatever the size), with the same interval
  const Json unsized =
      diagnose("inner_0.5_radial_p330",
               "--assume-defect inner --size-curve " +
                   test::write_temp("tiny_curve.txt",
                                    "# a curve below the record's area\n0.01 1e-12\n"
                                    "0.02 2e-12\n"));
  EXPECT_TRUE(unsized.find("size_interval_deg")->is_null());
  EXPECT_NE(unsized.find("size_method")->string().find("beyond the model's curve"),
            std::string::npos);
  EXPECT_NEAR(unsized.find("position_deg")->number(), inner.find("position_deg")->number(), 1e-9);
  EXPECT_EQ(unsized.find("position_reference")->string(), "shaft zero");
  EXPECT_NEAR((*unsized.find("position_interval_deg"))[0].number(), inner_iv[0].number(), 1e-9);
  // radial load, 0.3 deg outer pit at the load zone's centre: the jump is the load line's, and
  // the phase places the pit only modulo 360/13 deg, so the record cannot show it lies there
  // (pits 45-60 deg off read 20-25 % small): the reading is kept, the size not determined
  const Json outer = diagnose("outer_0.3_radial_p90", "--pulse-height 0.4494");
  EXPECT_EQ(outer.find("defect")->string(), "outer");
  EXPECT_TRUE(outer.find("size_deg")->is_null());
  EXPECT_NEAR(outer.find("size_reading_deg")->number(), 0.3, 0.03);
  EXPECT_NE(outer.find("size_method")->string().find("modulo the ball spacing"),
            std::string::npos);
  const auto place = [](const Json &j, double deg) {
    EXPECT_EQ(j.find("position_reference")->string(), "load direction");
    EXPECT_NEAR(j.find("position_modulo_deg")->number(), 360.0 / 13, 1e-9);
    EXPECT_NEAR(j.find("position_deg")->number(), deg, 1.5);
    const Json &iv = *j.find("position_interval_deg");
    EXPECT_LT(iv[0].number(), deg);
    EXPECT_GT(iv[1].number(), deg);
  };
  place(outer, 0);
  // a 2 deg outer pit 45 deg from the load (the deck's 135 deg): 45 - 2 x 360/13 = -10.38 deg
  place(diagnose("outer_2_radial_p135", "--pulse-height 0.4494"), 45 - 2 * 360.0 / 13);
}

// The pulses' edges: a held-out 3 deg inner pit under the radial load (same scene and
// chain as above), whose area has stopped growing (the ring drops into the gap, doc/methods/size_pulse_area.md
// "Size and position"): on the area's chain curve it reads far too small; on the width curve
// (width_inner_radial_r20000_low.txt, the study's runs at sizes none of which is 3 deg) its
// size is the deck's within 15 % (the goal) and the interval holds it.
TEST(Cli, DiagnoseSizesFromTheEdgesWhereTheAreaStopsGrowing)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  const std::string base = "diagnose " + data + "inner_3_radial_p90_20kHz.txt --column V " +
                           "--metadata " + data + "inner_3_radial_p90.json --format json " +
                           "--assume-defect inner --size-curve " + data +
                           "curve_inner_radial_r20000_low.txt";
  const CliRun area = run(base);
  ASSERT_EQ(area.status, 0) << area.out;
  const Json a = Json::parse(area.out, "diagnose output");
  EXPECT_LT(a.find("size_deg")->number(), 2.0);
  const CliRun width = run(base + " --width-curve " + data + "width_inner_radial_r20000_low.txt" +
                           " --width-model-error 0.02");
  ASSERT_EQ(width.status, 0) << width.out;
  const Json w = Json::parse(width.out, "diagnose output");
  EXPECT_NEAR(w.find("size_deg")->number(), 3.0, 0.45) << width.out;
  const Json &iv = *w.find("size_interval_deg");
  EXPECT_LE(iv[0].number(), 3.0);
  EXPECT_GE(iv[1].number(), 3.0);
  EXPECT_EQ(w.find("size_method")->string().rfind("pulse edges", 0), 0U);
  EXPECT_GT(w.find("pulse_edge_width_s")->number(), 0);
  const CliRun alone = run(base + " --width-model-error 0.02");
  EXPECT_NE(alone.status, 0);
  EXPECT_NE(alone.out.find("--width-model-error needs --width-curve"), std::string::npos)
      << alone.out;
}

// The template fit on a held-out simulated record where the area and the width fail:
// a 2 deg inner pit under the `force` load (the ring tightens within 55 us; the area's curve read
// it -83 %, the width saturates), the sizing study's run acquired at 20 kHz, 16 bits, low noise,
// first 0.15 s. The bank is studies/template_bank.py's for that scene and chain (runs at 0.2 ...
// 4.27 deg, 12 % apart: no 2 deg run; its own error in its header); on the full 0.3 s record the
// study reads 2 deg within 2 % (doc/methods/size_pulse_template.md), here within the 15 % of the goal.
TEST(Cli, DiagnoseSizesByTemplateWhereTheAreaAndWidthFail)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  const std::string bank = data + "bank_inner_force_r20000_low.txt";
  const std::string base = "diagnose " + data + "inner_2_force_p90_20kHz.txt --column V " +
                           "--metadata " + data + "inner_2_force_p90.json --format json " +
                           "--assume-defect inner";
  const CliRun r = run(base + " --size-method template --template-bank " + bank);
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out, "diagnose output");
  EXPECT_NEAR(j.find("size_deg")->number(), 2.0, 0.3) << r.out;
  const Json &iv = *j.find("size_interval_deg");
  EXPECT_LE(iv[0].number(), 2.0);
  EXPECT_GE(iv[1].number(), 2.0);
  EXPECT_EQ(j.find("size_method")->string().rfind("pulse template fit", 0), 0U)
      << j.find("size_method")->string();
  EXPECT_EQ(j.find("size_method_name")->string(), "template");
  EXPECT_EQ(j.find("size_status")->string(), "determined");
  // the method's own check: it needs the bank
  const CliRun no_bank = run(base + " --size-method template");
  EXPECT_NE(no_bank.status, 0);
  EXPECT_NE(no_bank.out.find("the template size method needs the model's bank"), std::string::npos)
      << no_bank.out;
  // a bank alone: the method chosen for an electrical record with a bank is the template fit
  const CliRun no_method = run(base + " --template-bank " + bank);
  ASSERT_EQ(no_method.status, 0) << no_method.out;
  EXPECT_EQ(Json::parse(no_method.out, "diagnose output").find("size_deg")->number(),
            j.find("size_deg")->number());
  // a bank of another defect
  const CliRun outer = run(base + " --size-method template --template-bank " + bank +
                           " --assume-defect outer");
  EXPECT_NE(outer.status, 0);
  EXPECT_NE(outer.out.find("for an inner defect, the one sized is outer"), std::string::npos)
      << outer.out;
}

TEST(Cli, DiagnoseRefusesABadTemplateBank)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  const std::string base = "diagnose " + data + "inner_2_force_p90_20kHz.txt --column V " +
                           "--metadata " + data + "inner_2_force_p90.json --format json " +
                           "--assume-defect inner --size-method template --template-bank ";
  const std::string good = test::slurp(data + "bank_inner_force_r20000_low.txt");
  auto refused = [&](const std::string &name, const std::string &text, const std::string &says) {
    const CliRun r = run(base + test::write_temp(name, text));
    EXPECT_NE(r.status, 0) << name;
    EXPECT_NE(r.out.find(says), std::string::npos) << name << ": " << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  };
  refused("bank_garbage.txt", "# bearing: machado2014\n0.5 0 3 1 2\n", "expected '# KEY: VALUE'");
  auto replaced = [&](const std::string &from, const std::string &to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  refused("bank_rate.txt", replaced("# sampling rate (Hz): 20000", "# sampling rate (Hz): 50000"),
          "the record is sampled at 20000 Hz");
  refused("bank_filter.txt", replaced("cut-off 8000 Hz", "cut-off 9000 Hz"),
          "through the anti-alias filter");
  refused("bank_bearing.txt", replaced("# bearing: machado2014", "# bearing: 6205"),
          "for the bearing 6205");
  refused("bank_load.txt", replaced("# load: force", "# load: fixed"), "under the fixed load");
  refused("bank_angle_error.txt",
          replaced("# load: force", "# load: force\n# angle error (deg): -3"),
          "the angle error must lie in [0, 180) deg");
  // a template at another angle (15 deg) for one size only: sizes x angles no longer a full grid
  refused("bank_partial.txt", good + "2 15 8 0 0 0 0 0 0 0 0 1 1 1 1 1 1 1 1\n", "a full grid");
  refused("bank_fold_period.txt", replaced("# load: force", "# load: force\n# fold period: exact"),
          "the fold period must be grid or fine");
}

// The fold's period: --fold-period fine states itself in the fold it writes, a bank
// without a '# fold period:' line was folded on the grid and refuses a record folded otherwise,
// a bank that states fine folds the record alike by itself, and a bad value names the option.
TEST(Cli, DiagnoseFoldPeriodFollowsTheBank)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  const std::string bank = data + "bank_inner_force_r20000_low.txt";
  const std::string base = "diagnose " + data + "inner_2_force_p90_20kHz.txt --column V " +
                           "--metadata " + data + "inner_2_force_p90.json --format json " +
                           "--assume-defect inner";
  const std::string fold = ohmdem::test::temp_dir().string() + "/fold_period.txt";
  const CliRun fine = run(base + " --no-size --fold-period fine --pulse-fold-out " + fold);
  ASSERT_EQ(fine.status, 0) << fine.out;
  EXPECT_NE(test::slurp(fold).find("# fold period: fine\n"), std::string::npos);
  const CliRun grid = run(base + " --no-size --pulse-fold-out " + fold);
  ASSERT_EQ(grid.status, 0) << grid.out;
  EXPECT_NE(test::slurp(fold).find("# fold period: grid\n"), std::string::npos);
  EXPECT_NE(test::slurp(fold).find("# bins no pass fell in: 0\n"), std::string::npos);
  const CliRun mixed =
      run(base + " --size-method template --template-bank " + bank + " --fold-period fine");
  EXPECT_NE(mixed.status, 0);
  EXPECT_NE(mixed.out.find("folds were made at the grid period"), std::string::npos) << mixed.out;
  std::string text = test::slurp(bank);
  text.replace(text.find("# load: force"), 13, "# load: force\n# fold period: fine");
  const CliRun stated = run(base + " --size-method template --template-bank " +
                            test::write_temp("bank_fine.txt", text) + " --pulse-fold-out " + fold);
  ASSERT_EQ(stated.status, 0) << stated.out;
  EXPECT_NE(test::slurp(fold).find("# fold period: fine\n"), std::string::npos);
  const CliRun bad = run(base + " --fold-period exact");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("--fold-period must be grid or fine, got 'exact'"), std::string::npos)
      << bad.out;
}

// An inner pit's place on the ring from a once-per-revolution tachometer ("a shaft
// angle: the deck's angle_inner, or a once-per-revolution tachometer column"): the held-out
// 0.5 deg pit at 330 deg with its angle column turned into the pulse a keyphasor gives (5 V for
// the first 10 deg of each turn). The tachometer's zero is the shaft's: the same place as the
// angle column's, within the edge's timing (half a sample: 0.7 deg of shaft at 20 kHz).
TEST(Cli, DiagnosePlacesAnInnerPitFromATachoColumn)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  std::istringstream in(test::slurp(data + "inner_0.5_radial_p330_20kHz.txt"));
  std::string text, line;
  while (std::getline(in, line)) {
    if (line == "# time V angle_inner") {
      text += "# time V tacho\n";
      continue;
    }
    if (!line.empty() && line[0] != '#') {
      std::istringstream ls(line);
      std::string t, v;
      double th = 0;
      ls >> t >> v >> th;
      const double pi = ohmdem::test::kPi;
      line = t + " " + v + (std::fmod(th, 2 * pi) < 10 * pi / 180 ? " 5" : " 0");
    }
    text += line + "\n";
  }
  const std::string base = " --column V --metadata " + data +
                           "inner_0.5_radial_p330.json --format json --assume-defect inner "
                           "--pulse-height 0.4494";
  const CliRun angle = run("diagnose " + data + "inner_0.5_radial_p330_20kHz.txt" + base);
  const CliRun tacho = run("diagnose " + test::write_temp("inner_tacho.txt", text) + base +
                           " --tacho-column tacho");
  ASSERT_EQ(angle.status, 0) << angle.out;
  ASSERT_EQ(tacho.status, 0) << tacho.out;
  const Json ja = Json::parse(angle.out, "diagnose output");
  const Json jt = Json::parse(tacho.out, "diagnose output");
  EXPECT_EQ(jt.find("position_reference")->string(), "shaft zero");
  EXPECT_NEAR(jt.find("position_deg")->number(), 330, 3);
  EXPECT_NEAR(jt.find("position_deg")->number(), ja.find("position_deg")->number(), 1);
  const Json &iv = *jt.find("position_interval_deg");
  EXPECT_LE(iv[0].number(), 330);
  EXPECT_GE(iv[1].number(), 330);
  // the size's zone fit reads the passes at the shaft's angles too: alike within 0.1 %
  EXPECT_NEAR(jt.find("size_deg")->number(), ja.find("size_deg")->number(),
              1e-3 * ja.find("size_deg")->number());
}

// A bank's template with bins no pass fell in (its run's period a near whole number of samples:
// diagnose's fold gives those bins one error, 1000 times the largest other's) is left out of the
// fit, and the size's method says which and what to do (such a template
// fitted a record with empty bins of its own with no misfit).
TEST(Cli, DiagnoseLeavesOutATemplateWithBinsNoPassFellIn)
{
  const std::string data = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";
  std::istringstream in(test::slurp(data + "bank_inner_force_r20000_low.txt"));
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("3.036 0 ", 0) == 0) {  // the 3.036 deg template: every other pair of bins
      std::istringstream ls(line);
      std::vector<std::string> v;
      for (std::string t; ls >> t;) v.push_back(t);
      const std::size_t n = std::stoul(v[2]);
      double top = 0;
      for (std::size_t j = 0; j < n; ++j) top = std::max(top, std::stod(v[3 + n + j]));
      line = v[0] + " " + v[1] + " " + v[2];
      for (std::size_t j = 0; j < 2 * n; ++j)
        line += " " + (j >= n && ((j - n) / 2) % 2 ? std::to_string(1e3 * top) : v[3 + j]);
    }
    text += line + "\n";
  }
  const std::string base = "diagnose " + data + "inner_2_force_p90_20kHz.txt --column V " +
                           "--metadata " + data + "inner_2_force_p90.json --format json " +
                           "--assume-defect inner --size-method template --template-bank ";
  const CliRun whole = run(base + data + "bank_inner_force_r20000_low.txt");
  const CliRun holed = run(base + test::write_temp("bank_holed.txt", text));
  ASSERT_EQ(whole.status, 0) << whole.out;
  ASSERT_EQ(holed.status, 0) << holed.out;
  const auto method = [](const CliRun &r) {
    return Json::parse(r.out, "diagnose output").find("size_method")->string();
  };
  EXPECT_EQ(method(whole).find("left out"), std::string::npos) << method(whole);
  EXPECT_NE(method(holed).find("the bank's templates at 3.036 deg left out (bins no pass fell in: "
                               "the run's period a near whole number of samples; a longer run "
                               "fills them)"),
            std::string::npos)
      << method(holed);
  EXPECT_NE(method(holed).find("27 templates"), std::string::npos) << method(holed);
}

TEST(Cli, DiagnoseCsvAndTable)
{
  const std::string dir = make_run_dir("run_csv", "inner");
  const CliRun csv = run("diagnose " + dir + "/signal.txt --format csv");
  ASSERT_EQ(csv.status, 0) << csv.out;
  EXPECT_NE(csv.out.find("\ndefect,score,frequency_Hz,kinematic_Hz,size_deg,pulse_width_s,"),
            std::string::npos);
  EXPECT_NE(csv.out.find("\ninner,"), std::string::npos);
  const CliRun table = run("diagnose " + dir + "/signal.txt");
  ASSERT_EQ(table.status, 0);
  EXPECT_NE(table.out.find("defect:        inner"), std::string::npos) << table.out;
}

}  // namespace
}  // namespace ohmdem::post
