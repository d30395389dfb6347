// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post diagnose --other-bearing`, `--other-channel` and `--mains`: their bad input (the
// measured records they are for: validation/test_real_records_other_bearing.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_run.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;

TEST(Cli, OtherBearingAndMainsBadInput)
{
  std::string text;  // a record of its own: the options are refused before it is analysed
  for (int i = 0; i < 12000; ++i) text += std::to_string(std::sin(0.37 * i * i)) + "\n";
  const std::string file = test::write_temp("other_bad_input.txt", text);
  const std::string in = "diagnose " + file + " --rate 12000 --rpm 1797 --bearing 6203 ";
  CliRun r = run(in + "--other-bearing no_such_bearing");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("no_such_bearing"), std::string::npos) << r.out;
  r = run(in + "--other-bearing 6205_KG");  // Z and Dw only: no frequencies
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--other-bearing 6205_KG ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(") does not fix its defect frequencies (no pitch diameter and no factors)"),
            std::string::npos)
      << r.out;
  for (const char *bad : {"abc", "-50", "0", "50,x", ","}) {
    r = run(in + "--mains " + bad);
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_NE(r.out.find("--mains expects mains frequencies in Hz, comma-separated (e.g. 50 or "
                         "50,60), or 'none', got '"),
              std::string::npos)
        << bad << ": " << r.out;
  }
}

TEST(Cli, OtherChannelBadInput)
{
  std::string text, shorter;
  for (int i = 0; i < 12000; ++i) {
    const std::string line = std::to_string(std::sin(0.37 * i * i)) + "\n";
    text += line;
    if (i < 11000) shorter += line;
  }
  const std::string file = test::write_temp("channels_bad_input.txt", text);
  const std::string other = test::write_temp("channels_bad_other.txt", shorter);
  const std::string in = "diagnose " + file + " --rpm 1797 --bearing 6203 ";
  CliRun r = run(in + "--rate 12000 --other-file " + other);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--other-file " + other +
                       " holds 11000 samples at 12000 Hz, the record "
                       "12000 at 12000 Hz: the two channels must be recorded together"),
            std::string::npos)
      << r.out;
  r = run(in + "--rate 12000 --other-channel 2");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("column number 2 out of range 1..1"), std::string::npos) << r.out;
  r = run(in + "--rate 12000 --other-channel 1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("--other-channel 1 holds the record's own samples: name the other "
                       "bearing's sensor"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace ohmdem::post
