// SPDX-License-Identifier: GPL-2.0-or-later
// Which run a restart belongs to (src_fix/lib/writers/run_record.*): the record's bytes, the
// folder's run number, the previous run's files set aside, the parameters compared.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "temp_dir.h"
#include "writers/run_record.h"

namespace fs = std::filesystem;

TEST(RunRecord, BytesRoundTrip)
{
  ohmdem::RunRecord r{7, "{\"F\": 320, \"status\": \"running\"}\n"};
  ohmdem::RunRecord back;
  ASSERT_TRUE(ohmdem::decode_run_record(ohmdem::encode_run_record(r), back));
  EXPECT_EQ(back.run, 7);
  EXPECT_EQ(back.parameters, r.parameters);
  EXPECT_FALSE(ohmdem::decode_run_record("not a record", back));
}

TEST(RunRecord, NewRunCountsAndSetsThePreviousFilesAside)
{
  const std::string folder = ohmdem::test::temp_path("newrun");
  fs::create_directories(folder);
  EXPECT_EQ(ohmdem::folder_run_number(folder), 0);
  long run = 0;
  std::vector<std::string> renamed;
  ASSERT_EQ(ohmdem::begin_new_run(folder, {"restart.a", "restart.b"}, run, renamed), "");
  EXPECT_EQ(run, 1);
  EXPECT_TRUE(renamed.empty());
  std::ofstream(folder + "/restart.a") << "A";
  ASSERT_EQ(ohmdem::begin_new_run(folder, {"restart.a", "restart.b"}, run, renamed), "");
  EXPECT_EQ(run, 2);
  EXPECT_EQ(ohmdem::folder_run_number(folder), 2);
  ASSERT_EQ(renamed, std::vector<std::string>{"restart.a"});
  EXPECT_FALSE(fs::exists(folder + "/restart.a"));
  EXPECT_TRUE(fs::exists(folder + "/restart.a.previous"));
}

TEST(RunRecord, ParametersComparedWithoutTheRunsProgress)
{
  const std::string before =
      "{\"ohmdem_version\": \"0.1.0\", \"F\": 320, \"dt\": 1e-6, \"tend\": 0.25, "
      "\"lubricant\": \"VG68\", \"time_reached\": 0.1, \"status\": \"running\"}\n";
  std::vector<std::pair<std::string, std::string>> after = {{"ohmdem_version", "\"0.2.0\""},
                                                            {"F", "320"},
                                                            {"dt", "1e-06"},
                                                            {"tend", "0.5"},
                                                            {"time_reached", "0"},
                                                            {"status", "\"running\""}};
  auto changes = ohmdem::changed_parameters(before, after);
  // 1e-6 and 1e-06 are one value; the version, tend and the progress are not parameters;
  // a parameter gone is a change
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].key, "lubricant");
  EXPECT_EQ(changes[0].before, "\"VG68\"");
  EXPECT_EQ(changes[0].after, "");
  after[1].second = "200";
  changes = ohmdem::changed_parameters(before, after);
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_EQ(changes[0].key, "F");
  EXPECT_EQ(changes[0].before, "320");
  EXPECT_EQ(changes[0].after, "200");
}
