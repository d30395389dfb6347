// SPDX-License-Identifier: GPL-2.0-or-later
// Dump files (post/io/read_dump.h) on genuine LIGGGHTS 3.8 outputs (tests/post/data, made by
// data/in.fixtures): per-frame aggregates, several files, the step length, non-finite values.
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

// An independent per-frame aggregation of a dump column (plain stream parsing).
std::vector<std::pair<long, std::vector<double>>> frames(const std::string &path,
                                                         std::size_t column)
{
  std::ifstream in(path);
  std::string line;
  std::vector<std::pair<long, std::vector<double>>> out;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: TIMESTEP", 0) != 0) continue;
    long step = 0, n = 0;
    in >> step;
    std::getline(in, line);
    std::getline(in, line);  // NUMBER OF
    in >> n;
    std::getline(in, line);
    for (int k = 0; k < 4; ++k) std::getline(in, line);  // BOX BOUNDS + 3 lines
    std::getline(in, line);                              // ATOMS/ENTRIES header
    std::vector<double> vals;
    for (long r = 0; r < n; ++r) {
      std::getline(in, line);
      std::istringstream ls(line);
      double v = 0;
      for (std::size_t c = 0; c <= column; ++c) ls >> v;
      vals.push_back(v);
    }
    out.emplace_back(step, vals);
  }
  return out;
}

TEST(Readers, DumpCustomAggregatesPerFrame)
{
  const auto ref = frames(data("dump.atoms"), 7);  // vz
  ASSERT_EQ(ref.size(), 6u);
  for (Aggregate a : {Aggregate::Sum, Aggregate::Mean, Aggregate::Max, Aggregate::Count}) {
    const DumpSeries d = read_dump({data("dump.atoms")}, "vz", a);
    ASSERT_EQ(d.values.size(), ref.size());
    for (std::size_t k = 0; k < ref.size(); ++k) {
      const auto &v = ref[k].second;
      double sum = 0, mx = -1e300;
      for (double x : v) {
        sum += x;
        mx = std::max(mx, x);
      }
      const double want = a == Aggregate::Sum    ? sum
                          : a == Aggregate::Mean ? sum / static_cast<double>(v.size())
                          : a == Aggregate::Max  ? mx
                                                 : static_cast<double>(v.size());
      EXPECT_NEAR(d.values[k], want, 1e-12 * (1 + std::fabs(want))) << aggregate_name(a);
      EXPECT_EQ(d.steps[k], static_cast<double>(ref[k].first));
    }
  }
}

TEST(Readers, DumpLocalSeveralFilesSortedWithoutDuplicates)
{
  const auto ref = frames(data("dump.local"), 3);  // c_cpl[7]
  // the same file twice, and a second copy holding the frames in reverse order
  std::string reversed;
  {
    std::ifstream in(data("dump.local"));
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string all = ss.str();
    std::vector<std::string> blocks;
    std::size_t pos = 0;
    while ((pos = all.find("ITEM: TIMESTEP", pos)) != std::string::npos) {
      const std::size_t next = all.find("ITEM: TIMESTEP", pos + 1);
      blocks.push_back(all.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
      pos = next == std::string::npos ? all.size() : next;
    }
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) reversed += *it;
  }
  const std::string rev = write_temp("dump_reversed.local", reversed);
  const DumpSeries d = read_dump({rev, data("dump.local")}, "c_cpl[7]", Aggregate::Sum);
  EXPECT_EQ(d.frames, 12u);
  EXPECT_EQ(d.duplicates, 6u);
  ASSERT_EQ(d.values.size(), ref.size());
  for (std::size_t k = 0; k < ref.size(); ++k) {
    double sum = 0;
    for (double x : ref[k].second) sum += x;
    EXPECT_NEAR(d.values[k], sum, 1e-12);
  }
  // an empty frame (no contact at step 24000) cannot be averaged
  expect_error([&] { read_dump({data("dump.local")}, "c_cpl[7]", Aggregate::Mean); },
               "has no rows to aggregate with 'mean'");
  expect_error([&] { read_dump({data("dump.local")}, "", Aggregate::Sum); },
               "choose a dump column with column NAME|N (columns: c_cpl[1] c_cpl[2]");
}

TEST(Readers, DumpAsSignalNeedsTheStepLength)
{
  InputOptions o;
  o.files = {data("dump.atoms")};
  o.column = "vz";
  expect_error([&] { load_signal(o, {}); }, "pass dt SECONDS");
  RunMetadata m;
  m.path = "run.json";
  m.dt = 2.5e-5;
  const Signal s = load_signal(o, m);  // dt from the run's metadata
  EXPECT_NEAR(s.rate, 1 / (4000 * 2.5e-5), 1e-9);
}

TEST(Readers, DumpFrameWithANonFiniteValueFailsOnlyWhenUsed)
{
  // the last frame of dump.atoms gets a NaN velocity: the frame's value is NaN, reported only
  // if the window holds it
  std::ifstream in(data("dump.atoms"));
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::size_t last = text.rfind("ITEM: ATOMS");
  const std::size_t row = text.find('\n', last) + 1;
  const std::size_t end = text.find('\n', row);
  std::istringstream cells(text.substr(row, end - row));
  std::string cell, edited;
  for (int c = 0; cells >> cell; ++c) edited += (c ? " " : "") + (c == 7 ? "nan" : cell);  // vz
  text.replace(row, end - row, edited);
  const std::string p = write_temp("nan.dump", text);
  const DumpSeries d = read_dump({p}, "vz", Aggregate::Max);
  EXPECT_TRUE(std::isnan(d.values.back()));
  EXPECT_TRUE(std::isfinite(d.values.front()));
  InputOptions o;
  o.files = {p};
  o.column = "vz";
  o.aggregate = Aggregate::Max;
  o.dt = 2.5e-5;
  expect_error([&] { load_signal(o, {}); }, "non-finite value (NaN) in column vz at t = ");
  o.to = d.steps[d.steps.size() - 2] * o.dt;
  EXPECT_EQ(load_signal(o, {}).size(), d.steps.size() - 1);
}

}  // namespace
}  // namespace ohmdem::post
