// SPDX-License-Identifier: GPL-2.0-or-later
// Thermo blocks of a LIGGGHTS 3.8 log (post/io/read_log.h).
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

TEST(Readers, LogThermoBlocks)
{
  const auto blocks = read_log(data("liggghts.log"));
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].table.column_list(), "Step Atoms KinEng rke heattran Volume");
  EXPECT_EQ(blocks[0].timestep, 2.5e-5);
  EXPECT_EQ(blocks[1].table.rows(), 21u);  // steps 1, 1000, ..., 20000
  EXPECT_GT(blocks[0].skipped, 0u);        // the INFO lines of the insertion
  // the whole log as one signal: step 0 and 1 of the first run make it non-uniform ...
  InputOptions o;
  o.files = {data("liggghts.log")};
  o.column = "KinEng";
  expect_error([&] { load_signal(o, {}); }, "non-uniform time stamps");
  // ... from step 1000 on it is uniform, with the time step read from the log; the repeated
  // first row of each later run is dropped
  o.from = 0.02;
  const Signal s = load_signal(o, {});
  EXPECT_EQ(s.size(), 24u);
  EXPECT_NEAR(s.rate, 1 / (1000 * 2.5e-5), 1e-9);
  EXPECT_DOUBLE_EQ(s.x.front(), blocks[1].table.columns[2][1]);
  EXPECT_DOUBLE_EQ(s.x.back(), blocks[2].table.columns[2].back());
}

}  // namespace
}  // namespace ohmdem::post
