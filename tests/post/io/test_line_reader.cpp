// SPDX-License-Identifier: GPL-2.0-or-later
// The line reader (post/io/line_reader.h): peeking, a UTF-8 byte order mark, the line length
// limit.
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

TEST(LineReader, PeekHandsTheFirstLineBackWithItsNumber)
{
  const std::string p = write_temp("peek.txt", "\n  \nLIGGGHTS (3.8)\nsecond\r\nlast");
  LineReader in(p);
  EXPECT_EQ(in.peek_first_content(), "LIGGGHTS (3.8)");
  EXPECT_EQ(in.peek_first_content(), "LIGGGHTS (3.8)");  // peeking again reads nothing more
  std::string line;
  std::vector<std::string> lines;
  while (in.next(line)) lines.push_back(line);
  // blank lines before it come back empty, the line endings are dropped, the line numbers are
  // those of the file
  const std::vector<std::string> want = {"", "", "LIGGGHTS (3.8)", "second", "last"};
  EXPECT_EQ(lines, want);
  EXPECT_EQ(in.line_number(), 5u);
}

TEST(LineReader, Utf8ByteOrderMarkIsSkipped)
{
  const std::string p = write_temp("bom.txt", "\xEF\xBB\xBF# time R\n0 1\n0.001 2\n0.002 4\n");
  const ColumnTable t = read_table(p);
  ASSERT_EQ(t.cols(), 2u);
  EXPECT_TRUE(t.has_header);
  EXPECT_EQ(t.names[0], "time");  // not "\xEF\xBB\xBFtime" or a comment missed
  EXPECT_EQ(t.columns[1][2], 4.0);
  const std::string plain = write_temp("bom_plain.txt",
                                       "\xEF\xBB\xBF"
                                       "1.5\n2.5\n");
  InputOptions o;
  o.files = {plain};
  o.rate = 10;
  EXPECT_EQ(load_signal(o, {}).x.front(), 1.5);
  expect_error(
      [] {
        read_table(write_temp("utf16.txt", std::string("\xFF\xFE"
                                                       "1\0",
                                                       4)));
      },
      "utf16.txt:1: UTF-16 text");
}

TEST(LineReader, LineLongerThanTheLimitNamesFileLineAndLimit)
{
  const std::string p = write_temp("long.txt", "1\n2\n" + std::string(100, '3') + "\n4\n");
  TableOptions o;
  o.max_line = 64;
  expect_error([&] { read_table(p, o); }, "long.txt:3: line longer than 64 bytes (no line break?)");
  o.max_line = 100;  // exactly at the limit is accepted
  EXPECT_EQ(read_table(p, o).rows(), 4u);
  // a file without any line break fails at the limit, without reading it whole
  const std::string nl = write_temp("no_newline.txt", std::string(3000, '7'));
  LineReader in(nl, 1000);
  std::string line;
  expect_error([&] { in.next(line); }, "no_newline.txt:1: line longer than 1000 bytes");
  EXPECT_LT(in.bytes_consumed(), 1001u);
}

}  // namespace
}  // namespace ohmdem::post
