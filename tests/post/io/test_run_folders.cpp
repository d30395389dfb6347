// SPDX-License-Identifier: GPL-2.0-or-later
// Finding run folders and their parameters (post/io/run_folders.h): natural order, sweep roots,
// the scalar keys of run.json, the varying parameter columns.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "dsp/stats.h"
#include "io/json.h"
#include "io/read_table.h"
#include "io/run_folders.h"
#include "io/table_select.h"
#include "synth.h"
#include "run_folder_fixtures.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::make_run;
using test::make_sweep;

TEST(CollectLib, ParameterKeysInCaseInsensitiveOrderAndVaryingOnes)
{
  const RunParameters one = {{"load", Json("fixed")}, {"F", Json(2.0)}, {"area", Json(1.0)}};
  const RunParameters two = {{"area", Json(1.0)}, {"load", Json("free")}, {"Z", Json(true)}};
  EXPECT_EQ(parameter_keys({&one, &two}, false),
            (std::vector<std::string>{"area", "F", "load", "Z"}));
  // area is the same in both; F and Z are missing in one; load differs
  EXPECT_EQ(parameter_keys({&one, &two}, true), (std::vector<std::string>{"F", "load", "Z"}));
  EXPECT_EQ(parameter_keys({&one}, true), (std::vector<std::string>{}));
  ASSERT_NE(find_parameter(two, "Z"), nullptr);
  EXPECT_TRUE(find_parameter(two, "Z")->boolean());
  EXPECT_EQ(find_parameter(two, "F"), nullptr);
}

TEST(CollectLib, NaturalOrder)
{
  std::vector<std::string> v = {"size_10", "size_2", "size_1.5", "a", "size_02", "B", "size_1"};
  std::sort(v.begin(), v.end(), natural_less);
  const std::vector<std::string> want = {"B",       "a",      "size_1", "size_1.5",
                                         "size_02", "size_2", "size_10"};
  EXPECT_EQ(v, want);
  EXPECT_FALSE(natural_less("x", "x"));
  EXPECT_TRUE(natural_less("run9", "run10"));
  EXPECT_FALSE(natural_less("run10", "run9"));
}

TEST(CollectLib, FindRunFolders)
{
  const std::string root = make_sweep("find");
  make_run(root + "/nested/deeper/run_b", R"({"x": 1})");
  make_run(root + "/.hidden/run_h", R"({"x": 1})");
  std::ofstream(root + "/figures/run.json") << "{}\n";  // run.json without signal.txt

  const RunFolders flat =
      find_run_folders({root + "/force_1", root + "/fixed_2/", root + "/no_metadata", root}, false);
  ASSERT_EQ(flat.runs.size(), 2u);
  EXPECT_EQ(flat.runs[0], root + "/fixed_2");
  EXPECT_EQ(flat.runs[1], root + "/force_1");
  ASSERT_EQ(flat.skipped.size(), 2u);  // the root (a container) and no_metadata
  EXPECT_EQ(flat.skipped[0].first, root);
  EXPECT_NE(flat.skipped[0].second.find("{runs.recursive} searches its subfolders"),
            std::string::npos);
  EXPECT_EQ(flat.skipped[1].first, root + "/no_metadata");
  EXPECT_EQ(flat.skipped[1].second, "no run.json");

  // recursive: natural order, hidden folders left out, half runs skipped, duplicates once
  const RunFolders rec = find_run_folders({root, root + "/fixed_10/signal.txt"}, true);
  const std::vector<std::string> want = {root + "/fixed_2", root + "/fixed_10", root + "/force_1",
                                         root + "/nested/deeper/run_b"};
  EXPECT_EQ(rec.runs, want);
  ASSERT_EQ(rec.skipped.size(), 2u);
  EXPECT_EQ(rec.skipped[0].first, root + "/figures");
  EXPECT_EQ(rec.skipped[0].second, "no signal.txt");
  EXPECT_EQ(rec.skipped[1].first, root + "/no_metadata");
  // the order of the arguments does not matter
  const RunFolders rev = find_run_folders({root + "/fixed_10/signal.txt", root}, true);
  EXPECT_EQ(rev.runs, rec.runs);
  EXPECT_EQ(rev.skipped, rec.skipped);

  const RunFolders none = find_run_folders({root + "/does_not_exist"}, true);
  EXPECT_TRUE(none.runs.empty());
  ASSERT_EQ(none.skipped.size(), 1u);
  EXPECT_EQ(none.skipped[0].second, "does not exist");
  const RunFolders empty = find_run_folders({root + "/figures"}, true);
  EXPECT_TRUE(empty.runs.empty());
  ASSERT_EQ(empty.skipped.size(), 1u);
  EXPECT_EQ(empty.skipped[0].second, "no signal.txt");
}

// A sweep root (ROOT/sweep_cases.csv, written by the sweep launchers): its cases without
// --recursive, in natural order; a listed case not run yet is said; unlisted folders are not
// collected.
TEST(CollectLib, FindRunFoldersOfASweepRoot)
{
  const std::string root = make_sweep("sweep_root");
  std::ofstream(root + "/sweep_cases.csv")
      << "case,load,size\n# a comment\nfixed_10,fixed,10\nfixed_2,fixed,2\nfixed_3,fixed,3\n";
  const RunFolders r = find_run_folders({root}, false);
  EXPECT_EQ(r.runs, (std::vector<std::string>{root + "/fixed_2", root + "/fixed_10"}));
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_EQ(r.skipped[0].first, root + "/fixed_3");
  EXPECT_EQ(r.skipped[0].second,
            "case of sweep_cases.csv line 5 not run (yet): no signal.txt and no run.json");

  std::ofstream(root + "/sweep_cases.csv") << "F,size\n1,2\n";  // not a sweep's copy
  const RunFolders bad = find_run_folders({root}, false);
  EXPECT_TRUE(bad.runs.empty());
  ASSERT_EQ(bad.skipped.size(), 1u);
  EXPECT_EQ(bad.skipped[0].second, "line 1: the first column is not 'case'");

  std::ofstream(root + "/sweep_cases.csv") << "case,size\n../force_1,1\n";
  const RunFolders outside = find_run_folders({root}, false);
  EXPECT_TRUE(outside.runs.empty());
  ASSERT_EQ(outside.skipped.size(), 1u);
  EXPECT_EQ(outside.skipped[0].second, "line 2: '../force_1' is not a case folder name");
}

TEST(CollectLib, RunParametersAreTheScalarKeys)
{
  const std::string root = make_sweep("params");
  std::vector<std::string> nonscalar;
  const auto p = run_parameters(root + "/fixed_2/run.json", &nonscalar);
  std::vector<std::string> keys;
  for (const auto &kv : p) keys.push_back(kv.first);
  const std::vector<std::string> want = {"defect",        "size_deg", "load",
                                         "t_sliding_end", "F",        "area"};
  EXPECT_EQ(keys, want);  // file order; null left out
  EXPECT_EQ(nonscalar, std::vector<std::string>{"tags"});
  EXPECT_EQ(p[1].second.number(), 2);
  EXPECT_EQ(p[5].second.string(), "greenwood, exact");
  EXPECT_THROW(run_parameters(root + "/no_metadata/run.json"), Error);
}

}  // namespace
}  // namespace ohmdem::post
