// SPDX-License-Identifier: GPL-2.0-or-later
// Column files (post/io/read_table.h) on genuine LIGGGHTS 3.8 outputs (tests/post/data, made by
// data/in.fixtures), and bad input refused with its line; only the columns used are stored.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "io/line_reader.h"
#include "io/load_signal.h"
#include "io/read_dump.h"
#include "io/read_log.h"
#include "io/read_table.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::expect_error;

using test::data;
using test::write_temp;

TEST(Readers, FixAveTimeFile)
{
  const ColumnTable t = read_table(data("avetime.txt"));
  ASSERT_TRUE(t.has_header);
  EXPECT_EQ(t.column_list(), "TimeStep c_rke c_thermo_temp");
  EXPECT_EQ(t.rows(), 24u);
  EXPECT_EQ(t.columns[0][0], 1000);
  EXPECT_EQ(t.find("c_rke"), 1u);
  EXPECT_EQ(t.find("3"), 2u);
  EXPECT_EQ(t.line_of_row[0], 3u);
}

TEST(Readers, FixPrintFileWithTitle)
{
  InputOptions o;
  o.files = {data("print.txt")};
  o.column = "rke";
  o.time_column = "step";
  o.dt = 2.5e-5;
  const Signal s = load_signal(o, {});
  EXPECT_EQ(s.size(), 48u);
  EXPECT_NEAR(s.rate, 1 / (500 * 2.5e-5), 1e-9);
  EXPECT_NEAR(s.t0, 500 * 2.5e-5, 1e-15);
}

TEST(Readers, BadInputIsRefusedWithItsLine)
{
  InputOptions o;
  o.rate = 100;
  auto run = [&](const std::string &file) {
    o.files = {file};
    return load_signal(o, {});
  };
  expect_error([&] { run(data("bad/empty.txt")); }, "empty file");
  expect_error([&] { run(data("bad/comments_only.txt")); }, "no data rows");
  expect_error([&] { run(data("bad/nan.txt")); }, "nan.txt:3: non-finite value (NaN)");
  expect_error([&] { run(data("bad/inf.txt")); }, "inf.txt:3: non-finite value (Inf)");
  expect_error([&] { run(data("bad/one_sample.txt")); }, "only 1 sample(s), at least 2 needed");
  expect_error([&] { run(data("bad/garbage.txt")); }, "garbage.txt:3: 2 values, expected 1");
  expect_error([&] { run(data("bad/garbage_word.txt")); }, "'hello' is not a number");
  expect_error([&] { run(data("bad/binary.dat")); }, "binary data");
  expect_error([&] { run(data("bad/missing.txt")); }, "cannot open");
  o.rate = 0;
  expect_error([&] { run(data("bad/nonuniform.txt")); }, "nonuniform.txt:5: non-uniform");
  expect_error([&] { run(data("bad/decreasing.txt")); },
               "decreasing.txt:4: time stamps not increasing");
  o.column = "X";
  expect_error([&] { run(data("bad/nonuniform.txt")); }, "unknown column 'X' (columns: time R)");
}

TEST(Readers, OnlyTheColumnsUsedAreStored)
{
  // our signal.txt layout: the loader keeps the time and the value, not the other columns, not a
  // string per row, and the line of each row costs nothing while the rows follow each other
  std::string text = "# time omega_cage fn_inner_mean n_contacts_race R n_masked\n";
  for (int i = 0; i < 5000; ++i)
    text += std::to_string(i * 1e-6) + " 198.05 24.6 26 " + std::to_string(1.39 + (i % 7) * 1e-3) +
            " 0\n";
  const std::string p = write_temp("six_columns.txt", text);
  TableOptions o;
  o.keep = [](const ColumnTable &t) {
    std::vector<bool> k(t.cols(), false);
    k[t.find("R")] = true;
    return k;
  };
  const ColumnTable t = read_table(p, o);
  EXPECT_EQ(t.rows(), 5000u);
  for (std::size_t c = 0; c < t.cols(); ++c)
    if (t.names[c] != "R") {
      EXPECT_EQ(t.columns[c].capacity(), 0u) << t.names[c];
    }
  EXPECT_EQ(t.columns[t.find("R")].size(), 5000u);
  // reserved from the file size after the first rows: no doubling (at most 25 % + 64 spare)
  EXPECT_LE(t.columns[t.find("R")].capacity(), 5000u * 5 / 4 + 64);
  EXPECT_EQ(t.line_of_row.runs(), 1u);
  EXPECT_EQ(t.line_of_row[4999], 5001u);
  EXPECT_EQ(t.text[t.find("R")].capacity(), 0u);
  // every cell is still checked, kept or not
  const std::string bad = write_temp("six_bad.txt", text + "0.1 198 x 26 1.4 0\n");
  expect_error([&] { read_table(bad, o); }, "six_bad.txt:5002: 'x' is not a number");
}

}  // namespace
}  // namespace ohmdem::post
