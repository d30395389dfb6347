// SPDX-License-Identifier: GPL-2.0-or-later
// Sizing and placing as a user runs them (`diagnose` with the record's run.json beside it, and
// `size`), on held-out simulated records (tests/post/data/sizing: the sizing study's runs of the
// 6208 at 500 rad/s, 50 um pits, acquired at 20 kHz, 16 bits, low noise; none used to build the
// banks). The reference is the size the deck was given.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli_run.h"
#include "io/json.h"
#include "temp_dir.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;

const std::string kData = std::string(OHMDEM_POST_TEST_DIR) + "/data/sizing/";

std::string read(const std::string &path)
{
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// run.json of the held-out 2 deg inner pit (force load) with `from` replaced by `to`
std::string metadata_with(const std::string &name, const std::string &from, const std::string &to)
{
  std::string j = read(kData + "inner_2_force_p90.json");
  for (std::size_t k = j.find(from); k != std::string::npos; k = j.find(from, k + to.size()))
    j.replace(k, from.size(), to);
  return test::write_temp(name, j);
}

Json json_of(const CliRun &r)
{
  EXPECT_EQ(r.status, 0) << r.out;
  return Json::parse(r.out, "diagnose output");
}

// One answer: where the template fit gives the size, no other size line stands above it (the
// pulse width's reading is a measurement, kept in the JSON's pulse_width).
TEST(Size, OneSizeLineAndItsMeasuredCoverage)
{
  const std::string base = "diagnose " + kData + "inner_2_force_p90_20kHz.txt --column V " +
                           "--metadata " + kData + "inner_2_force_p90.json --assume-defect inner " +
                           "--template-bank " + kData + "bank_inner_force_r20000_low.txt";
  const CliRun t = run(base);
  ASSERT_EQ(t.status, 0) << t.out;
  std::istringstream lines(t.out);
  std::string line, size_line;
  int sizes = 0;
  while (std::getline(lines, line))
    if (line.rfind("size", 0) == 0) ++sizes, size_line = line;
  EXPECT_EQ(sizes, 1) << t.out;
  EXPECT_NE(size_line.find("by template"), std::string::npos) << size_line;
  // the interval is labelled with the coverage the method's report measured
  EXPECT_NE(size_line.find("covered 114 of 120"), std::string::npos) << size_line;
  const Json j = json_of(run(base + " --format json"));
  EXPECT_NEAR(j.find("size_deg")->number(), 2.0, 0.3);
  EXPECT_EQ(j.find("size"), nullptr);  // the pulse width's old "size" object is gone
  EXPECT_NE(j.find("pulse_width"), nullptr);
}

// A run.json saying `custom` whose geometry is the bank's bearing's to the last digit is that
// bearing (matched by value, never by name); one digit off, it is another bearing.
TEST(Size, BankMatchedByTheGeometrysValuesNotItsName)
{
  const std::string bank = kData + "bank_inner_force_r20000_low.txt";
  const std::string rec = kData + "inner_2_force_p90_20kHz.txt --column V --assume-defect inner ";
  const Json named =
      json_of(run("diagnose " + rec + "--metadata " + kData + "inner_2_force_p90.json " +
                  "--template-bank " + bank + " --format json"));
  const std::string custom = metadata_with("custom_machado.json", "\"machado2014\"", "\"custom\"");
  const Json j = json_of(
      run("diagnose " + rec + "--metadata " + custom + " --template-bank " + bank +
          " --format json"));
  EXPECT_EQ(j.find("size_method_name")->string(), "template");
  EXPECT_DOUBLE_EQ(j.find("size_deg")->number(), named.find("size_deg")->number());
  // the same name with another ball diameter in its last digit: refused, the values named
  const std::string other =
      metadata_with("other_machado.json", "\"db\": 0.0126,", "\"db\": 0.0126001,");
  const CliRun r =
      run("diagnose " + rec + "--metadata " + other + " --template-bank " + bank + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("for the bearing machado2014 (13 balls of 12.6 mm on 60.6 mm"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("the record's is 13 balls of 12.6001 mm"), std::string::npos) << r.out;
}

// `size RECORD --model FILE`: the same answer as diagnose's, alone, whatever kind of model file;
// a file of no known kind is refused naming the forms.
TEST(Size, TheCommandWithOneModelOption)
{
  const std::string rec = kData + "inner_2_force_p90_20kHz.txt --column V --metadata " + kData +
                          "inner_2_force_p90.json --assume-defect inner ";
  const std::string bank = kData + "bank_inner_force_r20000_low.txt";
  const Json d = json_of(run("diagnose " + rec + "--template-bank " + bank + " --format json"));
  const Json s = json_of(run("size " + rec + "--model " + bank + " --format json"));
  EXPECT_DOUBLE_EQ(s.find("size_deg")->number(), d.find("size_deg")->number());
  EXPECT_EQ(s.find("size_status")->string(), "determined");
  EXPECT_EQ(s.find("families"), nullptr);  // the answer alone
  for (const char *key : {"size_interval_deg", "position_deg", "position_interval_deg",
                          "position_reference", "size_method"})
    EXPECT_NE(s.find(key), nullptr) << key;
  // a curve by the same option: the area's on the 3 deg fixed-load pit (its header says so)
  const Json c = json_of(run("size " + kData + "inner_3_fixed_p90_20kHz.txt --column V " +
                             "--metadata " + kData + "inner_3_fixed_p90.json --model " + kData +
                             "curve_inner_fixed.txt --format json"));
  EXPECT_NEAR(c.find("size_deg")->number(), 3.0, 0.06);
  // the model given twice, and a file of no known kind
  CliRun r = run("size " + rec + "--model " + bank + " --template-bank " + bank + " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("give the model data twice"), std::string::npos) << r.out;
  r = run("size " + rec + "--model " + test::write_temp("not_a_model.txt", "1 2\n3 4\n") +
          " 2>&1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("not a model file of a known kind; expected a bank of pulse templates"),
            std::string::npos)
      << r.out;
  // the help's example names options that exist
  const CliRun help = run("size --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("Example: ohmdem-post size V.txt --metadata run.json --model"),
            std::string::npos);
  EXPECT_NE(help.out.find("double-impulse"), std::string::npos);  // the table's names
}

// The model command's cache key is the scene's values: the bearing's name does not enter it, a
// load or a chain that differs does; without run.json there is no scene.
TEST(Size, ModelCacheKeyedByTheScenesValues)
{
  const std::string env = "OHMDEM_CACHE=" + ohmdem::test::temp_dir().string() + "/model_cache " +
                          std::string(OHMDEM_POST_EXE);
  auto key = [&](const std::string &meta, const std::string &extra = "") {
    const CliRun r = test::shell(env + " model " + kData +
                         "inner_2_force_p90_20kHz.txt --column V --metadata " + meta +
                         " --print-key " + extra);
    EXPECT_EQ(r.status, 0) << r.out;
    return r.out.substr(0, r.out.find(' '));
  };
  const std::string base = key(kData + "inner_2_force_p90.json");
  EXPECT_EQ(base.size(), 16u) << base;
  EXPECT_EQ(key(metadata_with("key_custom.json", "\"machado2014\"", "\"custom\"")), base);
  EXPECT_NE(key(metadata_with("key_load.json", "\"F\": 320,", "\"F\": 640,")), base);
  EXPECT_NE(key(kData + "inner_2_force_p90.json", "--defect outer"), base);
  const CliRun none = test::shell(env + " model " + kData +
                          "inner_2_force_p90_20kHz.txt --column V --no-metadata --print-key 2>&1");
  EXPECT_NE(none.status, 0);
  EXPECT_NE(none.out.find("needs its run.json"), std::string::npos) << none.out;
}

// The scene's words reach the engine as words, never through a shell: a run.json value holding
// a command is one argument of the engine (here a script that records its arguments and fails),
// and nothing runs it.
TEST(Size, ModelRunsTheEngineWithoutAShell)
{
  const std::string dir = ohmdem::test::temp_dir().string() + "/model_no_shell";
  const std::string args = dir + "/engine_args.txt";
  const std::string engine = test::write_temp(
      "model_no_shell_engine.sh",
      "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done >> \"$ARGS_FILE\"\nexit 1\n");
  const std::string meta = metadata_with("model_no_shell.json", "\"area\": \"greenwood\"",
                                         "\"area\": \"greenwood;touch PWNED\"");
  const CliRun r = test::shell("mkdir -p " + dir + " && cd " + dir + " && chmod +x " + engine +
                               " && ARGS_FILE=" + args + " OHMDEM_CACHE=" + dir + "/cache " +
                               std::string(OHMDEM_POST_EXE) + " model " + kData +
                               "inner_2_force_p90_20kHz.txt --column V --metadata " + meta +
                               " --engine " + engine + " --sizes 0.5,1,2 --jobs 1 2>&1");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("fewer than 3 of the 3 runs gave a fold"), std::string::npos) << r.out;
  const std::string seen = read(args);
  EXPECT_NE(seen.find("\ngreenwood;touch PWNED\n"), std::string::npos) << seen;
  EXPECT_FALSE(std::ifstream(dir + "/PWNED").good());
}

}  // namespace
}  // namespace ohmdem::post
