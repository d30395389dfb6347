// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post acquire` end to end: its record is read back by stats, spectrum and diagnose;
// round trip, CSV, warnings, the seed, the input rate option, input-referred noise.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;

std::string tmp(const std::string &name)
{
  return ohmdem::test::temp_dir().string() + "/" + name;
}

// A run as our decks write it: signal.txt (time, R at 1 MHz, 5 ms of sliding phase first) and
// run.json; returns the folder.
std::string make_run(const std::string &name, const std::string &kind, std::size_t *rows)
{
  const std::string dir = tmp(name);
  ::mkdir(dir.c_str(), 0755);
  test::DefectSpec spec;
  spec.kind = kind;
  spec.snr_db = 20;
  spec.duration = 0.15;
  const auto sig = test::defect_signal(bearing_preset("machado2014"), spec);
  std::ofstream out(dir + "/signal.txt");
  out << "# time omega_cage n_contacts_race R\n";
  char buf[128];
  for (std::size_t i = 0; i < 5000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 150 26 %.9g\n", i * 1e-6, 1.2 + 1e-4 * (i % 97));
    out << buf;
  }
  for (std::size_t i = 0; i < sig.signal.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 198.05 26 %.9g\n", (i + 5000) * 1e-6, sig.signal.x[i]);
    out << buf;
  }
  *rows = 5000 + sig.signal.size();
  std::ofstream(dir + "/run.json")
      << "{\"bearing\":\"machado2014\",\"omega_inner\":500.0,\"dt\":1e-6,\"defect\":\"" << kind
      << "\",\"t_sliding_end\":0.005}\n";
  return dir;
}

// The last '#' line before the data, and the data rows.
struct Record {
  std::string header;
  std::vector<std::vector<double>> rows;
};
Record read_record(const std::string &path)
{
  Record r;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') r.header = line;
  r.rows = test::read_rows(path);
  return r;
}

TEST(AcquireCli, BearingVoltageRecordIsReadByStatsSpectrumAndDiagnose)
{
  std::size_t n = 0;
  const std::string dir = make_run("acq_inner", "inner", &n);
  // 10 mA through R, 16 bits on 0..30 mV, 50 kHz behind a 20 kHz order-4 anti-alias filter
  const std::string rec = tmp("acq_inner_U.txt");
  const CliRun a = run("acquire " + dir +
                       "/signal.txt --scale 0.01 --lowpass 20000 --rate 50000 "
                       "--bits 16 --range 0 0.03 --noise-density 2e-8 --name U --unit V "
                       "--output " +
                       rec);
  ASSERT_EQ(a.status, 0) << a.out;
  EXPECT_EQ(a.out, "");  // no warning: nothing clipped, filtered
  const Record r = read_record(rec);
  EXPECT_EQ(r.header, "# time U");
  ASSERT_EQ(r.rows.size(), (n - 1) / 20 + 1);
  EXPECT_EQ(r.rows[0][0], 0);  // the input's clock
  EXPECT_NEAR(r.rows[1][0], 2e-5, 1e-15);
  const double q = 0.03 / 65536;
  for (const auto &row : r.rows) ASSERT_NEAR(row[1] / q, std::round(row[1] / q), 1e-6);
  const std::string text = test::slurp(rec);
  for (const char *m : {"# source: ", "# input column: R", "# scale: 0.01",
                        "# lowpass: Butterworth order 4, cut-off 20000 Hz",
                        "# sampling: every k-th sample of the input, k = 20",
                        "# adc: 16 bits, range 0 to 0.03", "# sampling rate (Hz): 50000"})
    EXPECT_NE(text.find(m), std::string::npos) << m;

  const CliRun st = run("stats " + rec + " --format json");
  ASSERT_EQ(st.status, 0) << st.out;
  const Json sj = Json::parse(st.out, "stats output");
  EXPECT_EQ(sj.find("n")->number(), static_cast<double>(r.rows.size()));
  EXPECT_NEAR(sj.find("mean")->number(), 0.0139, 0.0005);  // 10 mA x ~1.39 ohm

  const CliRun sp = run("spectrum " + rec + " --from 0.005 --peaks 3 --format json");
  ASSERT_EQ(sp.status, 0) << sp.out;
  EXPECT_NE(sp.out.find("\"sampling rate (Hz)\": \"50000\""), std::string::npos) << sp.out;

  // the original run's metadata: bearing, speed and its sliding phase (t < 5 ms, same clock)
  const CliRun d = run("diagnose " + rec + " --metadata " + dir + "/run.json --format json");
  ASSERT_EQ(d.status, 0) << d.out;
  const Json dj = Json::parse(d.out, "diagnose output");
  EXPECT_EQ(dj.find("defect")->string(), "inner");
  EXPECT_NE(dj.find("meta")->find("sliding phase skipped"), nullptr);
}

TEST(AcquireCli, WithoutOptionsTheColumnIsCopiedExactly)
{
  std::size_t n = 0;
  const std::string dir = make_run("acq_copy", "outer", &n);
  const std::string rec = tmp("acq_copy.txt");
  ASSERT_EQ(run("acquire " + dir + "/signal.txt --output " + rec).status, 0);
  const Record r = read_record(rec);
  EXPECT_EQ(r.header, "# time R");
  const auto in = test::read_rows(dir + "/signal.txt");
  ASSERT_EQ(r.rows.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    ASSERT_EQ(r.rows[i][1], in[i][3]) << i;  // shortest round-trip text: the same doubles
    ASSERT_NEAR(r.rows[i][0], in[i][0], 1e-12) << i;
  }
}

TEST(AcquireCli, CsvOutputIsReadBack)
{
  const std::string rec = tmp("acq_gauss.csv");
  const CliRun a = run("acquire " + test::reference("sig_gauss.txt") +
                       " --input-rate 1000 --lowpass 100 --rate 250 --format csv --output " + rec);
  ASSERT_EQ(a.status, 0) << a.out;
  const std::string text = test::slurp(rec);
  EXPECT_NE(text.find("\ntime,x\n0,"), std::string::npos) << text.substr(0, 2000);
  const CliRun st = run("stats " + rec + " --format json");
  ASSERT_EQ(st.status, 0) << st.out;
  EXPECT_EQ(Json::parse(st.out, "stats").find("n")->number(), 250);  // 1000 samples / 4
  // without --input-rate the loader's hint names the right option
  const CliRun no_rate = run("acquire " + test::reference("sig_gauss.txt"));
  EXPECT_NE(no_rate.status, 0);
  EXPECT_NE(no_rate.out.find("--input-rate"), std::string::npos) << no_rate.out;
}

TEST(AcquireCli, WarnsOnClippingAndOnSamplingWithoutFilter)
{
  const std::string in = test::reference("sig_gauss.txt");  // N(0.3, 1.7^2), 1000 values
  const CliRun c = run("acquire " + in + " --input-rate 1000 --bits 8 --range -1 1 --output " +
                       tmp("acq_clip.txt"));
  ASSERT_EQ(c.status, 0) << c.out;
  EXPECT_NE(c.out.find("WARNING: acquire: "), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("clipped at the ADC range [-1, 1]"), std::string::npos) << c.out;
  const CliRun al =
      run("acquire " + in + " --input-rate 1000 --rate 300 --output " + tmp("acq_alias.txt"));
  ASSERT_EQ(al.status, 0) << al.out;
  EXPECT_NE(al.out.find("without --lowpass: nothing stops aliasing"), std::string::npos) << al.out;
  EXPECT_NE(test::slurp(tmp("acq_alias.txt")).find("# sampling: cubic (4-point Lagrange)"),
            std::string::npos);
}

TEST(AcquireCli, SameSeedSameRecord)
{
  const std::string in = test::reference("sig_sine.txt");
  const std::string opts = " --input-rate 2048 --noise-rms 0.01 --bits 12 --range -1 1";
  ASSERT_EQ(run("acquire " + in + opts + " --seed 3 --output " + tmp("acq_s3a.txt")).status, 0);
  ASSERT_EQ(run("acquire " + in + opts + " --seed 3 --output " + tmp("acq_s3b.txt")).status, 0);
  ASSERT_EQ(run("acquire " + in + opts + " --seed 4 --output " + tmp("acq_s4.txt")).status, 0);
  EXPECT_EQ(test::slurp(tmp("acq_s3a.txt")), test::slurp(tmp("acq_s3b.txt")));
  EXPECT_NE(test::slurp(tmp("acq_s3a.txt")), test::slurp(tmp("acq_s4.txt")));
}

// The data rows of a record: each line's columns from `first` on (0: time).
std::vector<std::string> column_rows(const std::string &path, int first, int count)
{
  std::vector<std::string> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::vector<std::string> w;
    for (std::string x; f >> x;) w.push_back(x);
    std::string r;
    for (int k = first; k < first + count && k < static_cast<int>(w.size()); ++k) r += w[k] + " ";
    rows.push_back(r);
  }
  return rows;
}

TEST(AcquireCli, SecondAxisThroughTheSameChainWithItsOwnNoise)
{
  // two axes of one sensor: the second through the same chain as the first, its noise seeded
  // seed + 1, so each column is what a one-axis acquire of it gives with that seed
  std::string text = "# time a b\n";
  char buf[96];
  for (int i = 0; i < 30000; ++i) {  // 0.3 s: diagnose needs two cage periods
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", i * 1e-5, std::sin(0.01 * i),
                  0.5 * std::cos(0.013 * i));
    text += buf;
  }
  const std::string in = test::write_temp("acq_two_axes_in.txt", text);
  const std::string chain = " --lowpass 8000 --rate 20000 --noise-rms 0.01 --bits 16 --range -2 2";
  const CliRun both = run("acquire " + in + " --column a --across-column b --seed 3" + chain +
                          " --output " + tmp("acq_ab.txt"));
  ASSERT_EQ(both.status, 0) << both.out;
  ASSERT_EQ(run("acquire " + in + " --column a --seed 3" + chain + " --output " + tmp("acq_a.txt"))
                .status,
            0);
  ASSERT_EQ(run("acquire " + in + " --column b --seed 4" + chain + " --output " + tmp("acq_b.txt"))
                .status,
            0);
  const std::vector<std::string> ab = column_rows(tmp("acq_ab.txt"), 0, 3);
  const std::vector<std::string> a = column_rows(tmp("acq_a.txt"), 0, 2),
                                 b = column_rows(tmp("acq_b.txt"), 1, 1);
  ASSERT_EQ(ab.size(), 6000u);
  ASSERT_EQ(a.size(), ab.size());
  ASSERT_EQ(b.size(), ab.size());
  for (std::size_t i = 0; i < ab.size(); ++i) ASSERT_EQ(ab[i], a[i] + b[i]) << i;
  const std::string out = test::slurp(tmp("acq_ab.txt"));
  EXPECT_NE(out.find("# second axis: b (input b), the same chain, noise seed 4, clipped 0 of 6000\n"
                     "# time a b\n"),
            std::string::npos)
      << out.substr(0, 2000);
  // diagnose reads the pair
  const CliRun d = run("diagnose " + tmp("acq_ab.txt") +
                       " --column a --across-column b --size-method accel-curve --rpm 1800 "
                       "--bearing 6205 --no-size");
  EXPECT_EQ(d.status, 0) << d.out;
  EXPECT_NE(d.out.find("# second axis: b"), std::string::npos) << d.out;
  // bad input
  CliRun r = run("acquire " + in + " --column a --across-name x");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--across-name needs --across-column"), std::string::npos) << r.out;
  r = run("acquire " + in + " --column a --across-column a");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--across-column a holds the signal's own samples"), std::string::npos)
      << r.out;
  r = run("acquire " + in + " --column a --across-column b --name b");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("the two columns are both called 'b'"), std::string::npos) << r.out;
  r = run("acquire " + in + " --column a --across-column b --across-name 'x y'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("option --across-name expects one word"), std::string::npos) << r.out;
  r = run("acquire " + in + " --column a --across-column c");
  EXPECT_NE(r.status, 0);
}

TEST(AcquireCli, AccelerometerWithInputReferredNoiseDensity)
{
  // an acceleration (m/s^2) through a 100 mV/g = 10.197 mV/(m/s^2) sensor whose datasheet
  // density is 5e-4 (m/s^2)/sqrt(Hz): in volts 5e-4 x 0.010197 per sqrt(Hz), over 0..12800 Hz
  std::string text = "# time a\n";
  char buf[64];
  for (int i = 0; i < 20000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g %.9g\n", i * 1e-5,
                  3 * std::sin(2 * 3.14159 * 160 * i * 1e-5));
    text += buf;
  }
  const std::string in = test::write_temp("acq_accel_in.txt", text);
  const CliRun a = run("acquire " + in +
                       " --scale 0.010197 --noise-density 5e-4 --input-referred --lowpass 10000 "
                       "--rate 25600 --name v --unit V --output " +
                       tmp("acq_accel.txt"));
  ASSERT_EQ(a.status, 0) << a.out;
  const std::string out = test::slurp(tmp("acq_accel.txt"));
  char want[128];
  std::snprintf(want, sizeof want, "rms %.10g (density %.10g per sqrt(Hz) over 0 to rate/2 = 12800",
                5e-4 * 0.010197 * std::sqrt(12800.0), 5e-4 * 0.010197);
  EXPECT_NE(out.find(want), std::string::npos) << want << "\n" << out.substr(0, 3000);
  EXPECT_NE(out.find("cubic (4-point Lagrange) interpolation at 25600 Hz"), std::string::npos);
}

}  // namespace
}  // namespace ohmdem::post
