// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post spectrum` end to end: peaks as JSON, bins as CSV.
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

}  // namespace
}  // namespace ohmdem::post
