// SPDX-License-Identifier: GPL-2.0-or-later
// The source line of each row (post/core/row_lines.h), stored as runs of consecutive lines.
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

TEST(Readers, RowLinesMapRowsToTheirLines)
{
  RowLines l;
  for (std::size_t line : {3, 4, 5, 9, 10, 20}) l.push_back(line);
  EXPECT_EQ(l.size(), 6u);
  EXPECT_EQ(l.runs(), 3u);
  const std::size_t want[] = {3, 4, 5, 9, 10, 20};
  for (std::size_t r = 0; r < 6; ++r) EXPECT_EQ(l[r], want[r]);
  const RowLines s = l.slice(1, 5);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0], 4u);
  EXPECT_EQ(s[2], 9u);
  EXPECT_EQ(s[3], 10u);
  EXPECT_EQ(s.back(), 10u);
}

}  // namespace
}  // namespace ohmdem::post
