// SPDX-License-Identifier: GPL-2.0-or-later
// The command line end to end: our run layout (signal.txt + run.json), formats, commands.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "io/json.h"
#include "synth.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

struct CliRun {
  int status = -1;
  std::string out;
};

// Runs a shell command line (stdout and stderr together).
CliRun shell(const std::string &command)
{
  CliRun r;
  std::unique_ptr<FILE, int (*)(FILE *)> p(popen((command + " 2>&1").c_str(), "r"), pclose);
  if (!p) return r;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p.get())) r.out.append(buf, n);
  const int st = pclose(p.release());
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

CliRun run(const std::string &args)
{
  return shell(std::string(OHMDEM_POST_EXE) + " " + args);
}

// A run directory as our decks write it: signal.txt (R at 1 MHz) and run.json.
std::string make_run_dir(const std::string &name, const std::string &kind)
{
  const std::string dir = std::string(OHMDEM_POST_TEST_TMP) + "/" + name;
  ::mkdir(dir.c_str(), 0755);
  test::DefectSpec spec;
  spec.kind = kind;
  spec.snr_db = 20;
  spec.duration = 0.15;
  const auto sig = test::defect_signal(bearing_preset("6208"), spec);
  std::ofstream out(dir + "/signal.txt");
  out << "# time omega_cage fn_inner_mean fn_outer_mean n_contacts_race R n_masked\n";
  char buf[256];
  // a sliding phase of 5 ms first, with a different level, that the diagnosis must skip
  for (std::size_t i = 0; i < 5000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 150 24 24 26 %.9g 0\n", i * 1e-6, 1.2 + 1e-4 * (i % 97));
    out << buf;
  }
  for (std::size_t i = 0; i < sig.signal.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 198.05 24.6 24.6 26 %.9g 0\n", (i + 5000) * 1e-6,
                  sig.signal.x[i]);
    out << buf;
  }
  std::ofstream(dir + "/run.json")
      << "{\"bearing\":\"6208\",\"omega_inner\":500.0,\"nb\":13,\"db\":0.0126,\"dp\":0.0606,"
         "\"contact_angle\":0,\"dt\":1e-6,\"defect\":\""
      << kind << "\",\"size_deg\":1.0,\"load\":\"force\",\"F\":320,\"t_sliding_end\":0.005}\n";
  return dir;
}

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
    const Json *size = j.find("size");
    ASSERT_TRUE(size && size->find("size_deg"));
    EXPECT_NEAR(size->find("size_deg")->number(), 1.0, 0.05);
    // the sliding phase (t < 5 ms) was skipped as run.json says
    EXPECT_NE(j.find("meta")->find("sliding phase skipped"), nullptr);
  }
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

TEST(Cli, SpectrumPeaksAsJsonAndCsv)
{
  const std::string dir = make_run_dir("run_spec", "outer");
  const CliRun r = run("spectrum " + dir +
                       "/signal.txt --from 0.005 --pad 2 --fmax 3000 --peaks 3 "
                       "--format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out, "spectrum output");
  const Json *rows = j.find("rows");
  ASSERT_TRUE(rows && rows->size() == 3);
  // labelled with the defect frequencies from run.json
  EXPECT_EQ((*rows)[0].find("label")->string().find("BPFO") != std::string::npos, true);
  EXPECT_NE(j.find("columns")->dump(-1).find("amplitude_ohm"), std::string::npos);
  const CliRun c =
      run("spectrum " + dir + "/signal.txt --from 0.005 --bins --fmax 100 --format csv");
  ASSERT_EQ(c.status, 0);
  EXPECT_NE(c.out.find("\nfrequency_Hz,amplitude_ohm\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("# nfft: 150000"), std::string::npos);
}

TEST(Cli, EnvelopeKurtogramAndFrequencies)
{
  const std::string dir = make_run_dir("run_env", "inner");
  const CliRun k = run("envelope " + dir +
                       "/signal.txt --from 0.005 --show kurtogram --levels 3 "
                       "--format csv");
  ASSERT_EQ(k.status, 0) << k.out;
  EXPECT_NE(k.out.find("bands,f_low_Hz,f_high_Hz,center_Hz,spectral_kurtosis"), std::string::npos);
  const CliRun e = run("envelope " + dir +
                       "/signal.txt --from 0.005 --kurtogram --peaks 1 "
                       "--fmax 2000 --format json");
  ASSERT_EQ(e.status, 0) << e.out;
  const Json j = Json::parse(e.out, "envelope output");
  EXPECT_NE((*j.find("rows"))[0].find("label")->string().find("BPFI"), std::string::npos);
  const CliRun fb = run("envelope " + dir +
                        "/signal.txt --from 0.005 --kurtogram --fault-bands "
                        "--harmonics 2 --format csv");
  ASSERT_EQ(fb.status, 0) << fb.out;
  EXPECT_NE(fb.out.find("\nlabel,f_low_Hz,f_high_Hz,center_Hz,peak_amplitude_ohm,"
                        "peak_frequency_Hz,band_power_ohm^2\n"),
            std::string::npos)
      << fb.out;
  EXPECT_NE(fb.out.find("\n2xBPFI,"), std::string::npos);
  const CliRun f = run("frequencies --bearing 6208 --omega 500 --format json");
  ASSERT_EQ(f.status, 0);
  const Json fj = Json::parse(f.out, "frequencies output");
  EXPECT_NEAR(fj.find("bpfi_hz")->number(), 624.8, 0.05);
  EXPECT_NEAR(fj.find("two_bsf_hz")->number(), 366.18, 0.05);
}

TEST(Cli, StatsSlidingWindows)
{
  const std::string dir = make_run_dir("run_stats", "inner");
  const CliRun r = run("stats " + dir + "/signal.txt --window-length 0.05 --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json j = Json::parse(r.out, "stats output");
  ASSERT_EQ(j.find("windows")->size(), 3u);
  EXPECT_EQ(j.find("unit")->string(), "ohm");
}

TEST(Cli, DumpWithStepLengthFromTheLog)
{
  const CliRun r = run("stats " + test::data("dump.atoms") + " --column vz --aggregate max --log " +
                       test::data("liggghts.log") + " --format csv");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("# time base: time step x dt 2.5e-05 s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# sampling rate (Hz): 10"), std::string::npos) << r.out;
}

TEST(Cli, PlotsArePngFiles)
{
  if (!test::have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const std::string dir = make_run_dir("run_plot", "ball");
  const std::string sig = dir + "/signal.txt";
  struct Case {
    std::string args, png;
  };
  const Case cases[] = {
      {"--kind signal " + sig + " --from 0.005 --to 0.02", dir + "/signal.png"},
      {"--kind spectrum " + sig + " --from 0.005 --logy", dir + "/spectrum.png"},
      {"--kind envelope " + sig + " --from 0.005 --fmax 2000", dir + "/envelope.png"},
  };
  for (const auto &c : cases) {
    const CliRun r = run("plot " + c.args + " --output " + c.png);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(test::is_png(c.png)) << c.png;
  }
  // indicators versus a parameter, from a CSV written by stats
  const CliRun st =
      run("stats " + sig + " --window-length 0.02 --format csv --output " + dir + "/windows.csv");
  ASSERT_EQ(st.status, 0) << st.out;
  const CliRun r = run("plot --kind indicators " + dir +
                       "/windows.csv --x t_start_s --y "
                       "kurtosis,crest --output " +
                       dir + "/indicators.png");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(test::is_png(dir + "/indicators.png"));
  const CliRun bad = run("plot --kind indicators " + dir +
                         "/windows.csv --x nope --y kurtosis "
                         "--output " +
                         dir + "/x.png");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.out.find("ERROR: "), std::string::npos);
  EXPECT_NE(bad.out.find("unknown column 'nope'"), std::string::npos) << bad.out;
}

// The data lines of a CSV report (the '#' metadata name the source, which differs).
std::string csv_rows(const std::string &out)
{
  std::string rows, line;
  std::istringstream ss(out);
  while (std::getline(ss, line))
    if (line.empty() || line[0] != '#') rows += line + "\n";
  return rows;
}

// A signal.txt longer than a pipe's buffer (64 KiB) and than the reader's chunk, so that input
// read twice or only partly gives other numbers.
std::string big_signal()
{
  const std::string path = std::string(OHMDEM_POST_TEST_TMP) + "/stdin_signal.txt";
  std::ofstream out(path);
  out << "# time R\n";
  char buf[64];
  for (int i = 0; i < 20000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g %.9g\n", i * 1e-5, 1.39 + 0.01 * ((i * 7919) % 101));
    out << buf;
  }
  return path;
}

TEST(Cli, StandardInputPipeAndFifoReadLikeTheFile)
{
  const std::string sig = big_signal();
  const std::string exe = OHMDEM_POST_EXE;
  const CliRun file = run("stats --format csv " + sig);
  ASSERT_EQ(file.status, 0) << file.out;
  const std::string want = csv_rows(file.out);
  EXPECT_NE(want.find(",20000,"), std::string::npos) << want;  // every row read
  const std::string commands[] = {
      exe + " stats --format csv - < " + sig,                         // '-': a file on stdin
      "cat " + sig + " | " + exe + " stats --format csv -",           // '-': a pipe
      "cat " + sig + " | " + exe + " stats --format csv /dev/stdin",  // read once, not twice
  };
  for (const auto &c : commands) {
    const CliRun r = shell(c);
    EXPECT_EQ(r.status, 0) << c << "\n" << r.out;
    EXPECT_EQ(csv_rows(r.out), want) << c;
  }
  const CliRun named = run("stats --format csv - < " + sig);
  EXPECT_NE(named.out.find("# source: standard input"), std::string::npos) << named.out;
  // a FIFO (named pipe): the writer runs in the background
  const std::string fifo = std::string(OHMDEM_POST_TEST_TMP) + "/signal.fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const CliRun f =
      shell(exe + " stats --format csv " + fifo + " & cat " + sig + " > " + fifo + "; wait");
  EXPECT_EQ(csv_rows(f.out), want);
  std::remove(fifo.c_str());
  // standard input is read once: given twice it is an error, not an empty second read
  const CliRun twice = run("stats --log - - < " + sig);
  EXPECT_EQ(twice.status, 1);
  EXPECT_NE(twice.out.find("standard input ('-') can be read only once"), std::string::npos)
      << twice.out;
}

TEST(Cli, EndlessOrBinaryInputFailsWithBoundedMemory)
{
  // /dev/zero never ends: the NUL byte stops it at once; a file without a line break stops at
  // the line limit (1 MiB) instead of growing one line
  const CliRun z = run("stats /dev/zero --rate 10");
  EXPECT_EQ(z.status, 1);
  EXPECT_NE(z.out.find("ERROR: /dev/zero:1: binary data (NUL byte)"), std::string::npos) << z.out;
  const std::string p = test::write_temp("one_long_line.txt", std::string(1100000, '5'));
  const CliRun l = run("stats " + p + " --rate 10");
  EXPECT_EQ(l.status, 1);
  EXPECT_NE(l.out.find("one_long_line.txt:1: line longer than 1048576 bytes"), std::string::npos)
      << l.out;
}

TEST(Cli, FailedPlotLeavesNoFile)
{
  if (!test::have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  // a zero signal on a logarithmic axis: gnuplot fails after opening its output
  std::string text = "# time R\n";
  for (int i = 0; i < 256; ++i) text += std::to_string(i * 1e-3) + " 0\n";
  const std::string sig = test::write_temp("zero_signal.txt", text);
  const std::string png = std::string(OHMDEM_POST_TEST_TMP) + "/failed.png";
  std::remove(png.c_str());
  const CliRun r = run("plot --kind spectrum " + sig + " --logy --output " + png);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("ERROR: gnuplot failed writing"), std::string::npos) << r.out;
  struct stat st {};
  EXPECT_NE(::stat(png.c_str(), &st), 0) << "an empty or partial " << png << " was left";
  // an existing figure is left as it was
  std::ofstream(png) << "old figure";
  EXPECT_EQ(run("plot --kind spectrum " + sig + " --logy --output " + png).status, 1);
  EXPECT_EQ(test::slurp(png), "old figure");
  // and nothing else stays in the folder (the temporary image is removed)
  const CliRun ls = shell(std::string("ls -a ") + OHMDEM_POST_TEST_TMP);
  EXPECT_EQ(ls.out.find("failed.png.tmp"), std::string::npos) << ls.out;
}

}  // namespace
}  // namespace ohmdem::post
