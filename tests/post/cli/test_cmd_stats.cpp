// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post stats` end to end: sliding windows, a dump with the step length from the log.
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
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::make_run_dir;
using test::run;
using test::shell;

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

}  // namespace
}  // namespace ohmdem::post
