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

#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::make_run_dir;
using test::run;
using test::shell;

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

// A zero signal's spectrum on a logarithmic axis: a message of its own (not gnuplot's "all
// points y value undefined"), no file.
TEST(Cli, LogyOfAnAllZeroSpectrumIsAMessage)
{
  if (!test::have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  std::string text = "# time R\n";
  for (int i = 0; i < 256; ++i) text += std::to_string(i * 1e-3) + " 0\n";
  const std::string sig = test::write_temp("zero_signal.txt", text);
  const std::string png = ohmdem::test::temp_dir().string() + "/zero_logy.png";
  std::remove(png.c_str());
  const CliRun r = run("plot --kind spectrum " + sig + " --logy --output " + png);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out,
            "ERROR: plot --logy: no value of the figure is > 0 (spectrum: all zero or "
            "negative); a logarithmic axis has nothing to draw: plot without --logy\n");
  struct stat st {};
  EXPECT_NE(::stat(png.c_str(), &st), 0) << png << " was written";
  EXPECT_EQ(run("plot --kind spectrum " + sig + " --output " + png).status, 0);  // linear: drawn
}

TEST(Cli, FailedPlotLeavesNoFile)
{
  // a gnuplot that writes part of its image, then fails
  const std::string dir = ohmdem::test::temp_dir().string();
  const std::string fake =
      test::write_temp("failing_gnuplot",
                       "#!/bin/sh\nout=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\")\n"
                       "printf 'partial' > \"$out\"\necho 'gnuplot: it failed' >&2\nexit 1\n");
  ::chmod(fake.c_str(), 0755);
  std::string text = "# time R\n";
  for (int i = 0; i < 256; ++i)
    text += std::to_string(i * 1e-3) + " " + std::to_string(i % 5) + "\n";
  const std::string sig = test::write_temp("ramp_signal.txt", text);
  const std::string png = dir + "/failed.png";
  std::remove(png.c_str());
  const std::string plot = "OHMDEM_GNUPLOT=" + fake + " " + OHMDEM_POST_EXE +
                           " plot --kind spectrum " + sig + " --output " + png;
  const CliRun r = shell(plot);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("ERROR: gnuplot failed writing"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gnuplot: it failed"), std::string::npos) << r.out;
  struct stat st {};
  EXPECT_NE(::stat(png.c_str(), &st), 0) << "an empty or partial " << png << " was left";
  // an existing figure is left as it was
  std::ofstream(png) << "old figure";
  EXPECT_EQ(shell(plot).status, 1);
  EXPECT_EQ(test::slurp(png), "old figure");
  // and nothing else stays in the folder (the temporary image is removed)
  const CliRun ls = shell("ls -a " + dir);
  EXPECT_EQ(ls.out.find("failed.png.tmp"), std::string::npos) << ls.out;
}

}  // namespace
}  // namespace ohmdem::post
