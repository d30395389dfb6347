// SPDX-License-Identifier: GPL-2.0-or-later
// Order tracking, spectrogram and MAT input through the command line: a run-up with an inner-race
// defect (impulses at 5.4152 orders, the 6205's BPFI/fr, ringing a 1 kHz resonance) whose speed
// comes from an angle column, an rpm column or our angle_inner; diagnose switches to orders.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "bearing/bearing.h"
#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;

using ohmdem::test::kPi;

double bpfi_order()
{
  return defect_frequencies(bearing_preset("6205"), 1.0).bpfi;
}

// fs 4 kHz, 3 s, shaft 15 -> 25 Hz; columns time angle_inner speed_rpm x
std::string run_up_file()
{
  static const std::string path = [] {
    const double fs = 4000, o = bpfi_order();
    const std::size_t n = 12000;
    std::vector<double> t(n), th(n), x(n);
    test::Gaussian g(42);
    for (std::size_t i = 0; i < n; ++i) {
      t[i] = i / fs;
      th[i] = 2 * kPi * (15 * t[i] + 5 / 3.0 * t[i] * t[i]);
      x[i] = 0.2 * g();
    }
    // an impulse each time the defect angle passes a multiple of 2 pi / o, ringing at 1 kHz
    for (std::size_t i = 1; i < n; ++i)
      if (std::floor(o * th[i] / (2 * kPi)) > std::floor(o * th[i - 1] / (2 * kPi)))
        for (std::size_t j = 0; j < 40 && i + j < n; ++j)
          x[i + j] += std::exp(-static_cast<double>(j) / 6) * std::sin(2 * kPi * 1000 * j / fs);
    std::string text = "# time angle_inner speed_rpm x\n";
    char buf[160];
    for (std::size_t i = 0; i < n; ++i) {
      std::snprintf(buf, sizeof buf, "%.9g %.17g %.17g %.9g\n", t[i], th[i],
                    60 * (15 + 10 / 3.0 * t[i]), x[i]);
      text += buf;
    }
    return test::write_temp("run_up.txt", text);
  }();
  return path;
}

const Json &get(const Json &j, const std::string &key)
{
  static const Json null;
  const Json *v = j.find(key);
  EXPECT_NE(v, nullptr) << "no key " << key;
  return v ? *v : null;
}

Json first_peak(const std::string &out)
{
  const Json j = Json::parse(out);
  const Json &rows = get(j, "rows");
  EXPECT_GT(rows.size(), 0u) << out;
  return rows.size() ? rows[0] : Json();
}

TEST(OrdersCli, EnvelopeOrderSpectrumFindsBpfiFromTheAngleColumn)
{
  const CliRun r = run("orders " + run_up_file() +
                       " --column x --bearing 6205 --envelope --band 700 1300 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json p = first_peak(r.out);
  EXPECT_EQ(get(p, "label").string(), "1xBPFI") << r.out;
  EXPECT_NEAR(get(p, "order").number(), bpfi_order(), 1e-3 * bpfi_order());
  EXPECT_NE(r.out.find("column angle_inner (rad)"), std::string::npos);
}

TEST(OrdersCli, SpeedColumnInRpmGivesTheSameOrder)
{
  const CliRun a = run("orders " + run_up_file() +
                       " --column x --bearing 6205 --envelope --band 700 1300 --format json "
                       "--speed-column speed_rpm --speed-unit rpm");
  ASSERT_EQ(a.status, 0) << a.out;
  EXPECT_NE(a.out.find("speed_rpm (rpm), integrated"), std::string::npos);
  const Json p = first_peak(a.out);
  EXPECT_EQ(get(p, "label").string(), "1xBPFI");
  EXPECT_NEAR(get(p, "order").number(), bpfi_order(), 1e-3 * bpfi_order());
}

// The run-up's shaft as an instrument records it: a once-per-revolution pulse (5 V for the first
// 20 deg of each turn, edges 2 samples long at 15-25 Hz) instead of the angle.
std::string run_up_tacho_file()
{
  std::ifstream in(run_up_file());
  std::string line, out = "# time tacho x\n";
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string t, rpm, x;
    double th = 0;
    ls >> t >> th >> rpm >> x;
    out += t + (std::fmod(th, 2 * kPi) < 20 * kPi / 180 ? " 5 " : " 0 ") + x + "\n";
  }
  return test::write_temp("run_up_tacho.txt", out);
}

TEST(OrdersCli, TachoColumnGivesTheSameOrder)
{
  const CliRun a = run("orders " + run_up_tacho_file() +
                       " --column x --bearing 6205 --envelope --band 700 1300 --format json "
                       "--tacho-column tacho");
  ASSERT_EQ(a.status, 0) << a.out;
  EXPECT_NE(a.out.find("column tacho, 59 once-per-revolution pulses"), std::string::npos) << a.out;
  const Json p = first_peak(a.out);
  EXPECT_EQ(get(p, "label").string(), "1xBPFI");
  EXPECT_NEAR(get(p, "order").number(), bpfi_order(), 1e-3 * bpfi_order());
  const CliRun both = run("orders " + run_up_tacho_file() +
                          " --column x --bearing 6205 --tacho-column tacho --angle-column 2");
  EXPECT_NE(both.status, 0);
  EXPECT_NE(both.out.find("give the shaft angle once: --angle-column, --speed-column or "
                          "--tacho-column"),
            std::string::npos)
      << both.out;
  std::string text = test::slurp(run_up_tacho_file());
  for (std::size_t at = 0; (at = text.find(" 5 ", at)) != std::string::npos;) text[at + 1] = '0';
  const CliRun flat = run("orders " + test::write_temp("run_up_no_pulse.txt", text) +
                          " --column x --bearing 6205 --tacho-column tacho");
  EXPECT_NE(flat.status, 0);
  EXPECT_NE(flat.out.find("--tacho-column tacho: tachometer column: flat"), std::string::npos)
      << flat.out;
}

// A toothed wheel of 4 teeth: 4 pulses per revolution (5 V for the first 5 deg of each quarter
// turn); with --tacho-ppr 4 the angle, hence the BPFI order, is the run-up's own.
TEST(OrdersCli, TachoPulsesPerRevolution)
{
  std::ifstream in(run_up_file());
  std::string line, text = "# time tacho x\n";
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string t, rpm, x;
    double th = 0;
    ls >> t >> th >> rpm >> x;
    text += t + (std::fmod(th, kPi / 2) < 5 * kPi / 180 ? " 5 " : " 0 ") + x + "\n";
  }
  const std::string file = test::write_temp("run_up_tacho4.txt", text);
  const CliRun a = run("orders " + file +
                       " --column x --bearing 6205 --envelope --band 700 1300 --format json "
                       "--tacho-column tacho --tacho-ppr 4");
  ASSERT_EQ(a.status, 0) << a.out;
  EXPECT_NE(a.out.find("pulses at 4 per revolution (--tacho-ppr"), std::string::npos) << a.out;
  const Json p = first_peak(a.out);
  EXPECT_EQ(get(p, "label").string(), "1xBPFI");
  EXPECT_NEAR(get(p, "order").number(), bpfi_order(), 1e-3 * bpfi_order());
  const CliRun alone = run("orders " + file + " --column x --bearing 6205 --tacho-ppr 4");
  EXPECT_NE(alone.status, 0);
  EXPECT_NE(alone.out.find("--tacho-ppr gives the pulses per revolution of a --tacho-column"),
            std::string::npos)
      << alone.out;
  const CliRun zero = run("orders " + file + " --column x --bearing 6205 --tacho-column tacho "
                          "--tacho-ppr 0");
  EXPECT_NE(zero.status, 0);
  EXPECT_NE(zero.out.find("option --tacho-ppr expects a pulse count per revolution in 1..10000"),
            std::string::npos)
      << zero.out;
}

// One speed option per unit: --fr is refused, naming --shaft-hz
TEST(OrdersCli, FrRefusedNamingShaftHz)
{
  const CliRun r = run("frequencies --bearing 6205 --fr 29.95");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("frequencies: option --fr is not taken any more: give the shaft frequency "
                       "in Hz with --shaft-hz"),
            std::string::npos)
      << r.out;
}

TEST(OrdersCli, DiagnoseSwitchesToOrdersWhenTheSpeedVaries)
{
  const CliRun r = run("diagnose " + run_up_file() + " --column x --bearing 6205 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(get(j, "domain").string(), "orders");
  EXPECT_EQ(get(j, "defect").string(), "inner") << r.out;
  // frequencies are orders x the mean shaft frequency (20 Hz over 0..3 s)
  EXPECT_NEAR(get(j, "frequency_hz").number() / get(j, "shaft_hz").number(), bpfi_order(),
              2e-3 * bpfi_order());
  // the shaft frequency the spectrum gives is in Hz too (it was left in orders, ~1)
  const Json &est = get(j, "shaft_hz_from_spectrum");
  ASSERT_FALSE(est.is_null());  // from the shaft or the BPFI comb
  EXPECT_NEAR(est.number(), get(j, "shaft_hz").number(), 0.02 * get(j, "shaft_hz").number());
  // the same record at its mean speed, without the angle, is not recognised as inner
  const std::string flat = test::write_temp("run_up_no_angle.txt", [] {
    std::ifstream in(run_up_file());
    std::string line, out = "# time x\n";
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::istringstream ls(line);
      std::string c0, c1, c2, c3;
      ls >> c0 >> c1 >> c2 >> c3;
      out += c0 + " " + c3 + "\n";
    }
    return out;
  }());
  const CliRun c = run("diagnose " + flat + " --bearing 6205 --rpm 1200 --format json");
  ASSERT_EQ(c.status, 0) << c.out;
  const Json jc = Json::parse(c.out);
  EXPECT_EQ(get(jc, "domain").string(), "time");
  EXPECT_NE(get(jc, "defect").string(), "inner");
}

TEST(OrdersCli, ConstantSpeedFromRunOptionsAndMatVariables)
{
  // a .mat record at constant speed: a 50 Hz line (on a ramp, detrended) at 1797 rpm (29.95
  // Hz) is order 1.6694
  const std::string mat = test::data("mat/good.mat");
  const CliRun r = run("orders " + mat +
                       " --variable x --rate-variable fs --rpm-variable RPM --format json "
                       "--samples-per-rev 32 --peaks 1 --detrend linear");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NEAR(get(first_peak(r.out), "order").number(), 50 / (1797 / 60.0), 0.02);
  EXPECT_NE(r.out.find("MAT variable RPM"), std::string::npos);
}

TEST(OrdersCli, SpectrogramPng)
{
  if (!test::have_gnuplot()) GTEST_SKIP() << "gnuplot not found";
  const std::string png = ohmdem::test::temp_dir().string() + "/spectrogram.png";
  std::remove(png.c_str());
  const CliRun r = run("plot --kind spectrogram " + run_up_file() +
                       " --column x --bearing 6205 --fmax 1500 --output " + png);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(test::is_png(png));
}

TEST(OrdersCli, MatStatsEqualTheTextOnesForTheFixture)
{
  const CliRun r =
      run("stats " + test::data("mat/good.mat") + " --variable x --rate 1000 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(get(j, "n").number(), 300);
  EXPECT_NE(r.out.find("MATLAB MAT-file"), std::string::npos);
}

}  // namespace
}  // namespace ohmdem::post
