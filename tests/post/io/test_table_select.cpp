// SPDX-License-Identifier: GPL-2.0-or-later
// Row selection in a table (post/io/table_select.h): `--where` conditions on text and numbers.
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
#include "test_util.h"

namespace ohmdem::post {
namespace {

namespace fs = std::filesystem;

TEST(CollectLib, TableSelectWhere)
{
  const std::string path = test::write_temp("collect_where.csv",
                                            "# comment\n"
                                            "run,load,size_deg,kurtosis\n"
                                            "a,fixed,1,3.5\n"
                                            "b,force,1.5,\n"
                                            "c,fixed,2,2.25\n"
                                            "d,,2,2\n");
  const ColumnTable t = read_table(path);
  ASSERT_EQ(t.rows(), 4u);
  const std::size_t load = t.find("load");
  ASSERT_EQ(t.text[load].size(), 4u);
  EXPECT_EQ(t.text[load][1], "force");
  EXPECT_EQ(t.text[load][3], "");
  EXPECT_TRUE(t.text[t.find("size_deg")].empty());  // numbers only
  EXPECT_EQ(select_rows(t, "load=fixed"), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(select_rows(t, "load!=fixed"), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(select_rows(t, "load=fixed, size_deg=2.0"), (std::vector<std::size_t>{2}));
  EXPECT_EQ(select_rows(t, "size_deg=1.5"), (std::vector<std::size_t>{1}));
  EXPECT_EQ(select_rows(t, ""), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(select_rows(t, "load=none").empty());
  EXPECT_THROW(select_rows(t, "nope=1"), Error);
  EXPECT_THROW(select_rows(t, "load"), Error);
  std::size_t undefined = 0;
  EXPECT_EQ(defined_rows(t, t.find("kurtosis"), {0, 1, 2, 3}, &undefined),
            (std::vector<std::size_t>{0, 2, 3}));
  EXPECT_EQ(undefined, 1u);
  EXPECT_THROW(defined_rows(t, t.find("run"), {0}), Error);
}

}  // namespace
}  // namespace ohmdem::post
