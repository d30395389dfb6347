// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post plot` end to end: PNG files, and no file left by a failed plot.
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
  const auto sig = test::defect_signal(bearing_preset("machado2014"), spec);
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
