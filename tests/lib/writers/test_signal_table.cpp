// SPDX-License-Identifier: GPL-2.0-or-later
// The signal table writer: every value reads back to the same double, the header, buffering
// and flushing, and continuing a file after a restart (rows after the restart point dropped,
// a line cut by a crash dropped, another header refused).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "temp_dir.h"
#include "writers/signal_table.h"

using ohmdem::test::temp_path;

namespace {

std::string slurp(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::vector<double>> read_rows(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> r;
    std::string w;
    while (ls >> w) r.push_back(std::strtod(w.c_str(), nullptr));
    rows.push_back(r);
  }
  return rows;
}

ohmdem::SignalTable::Options options(const std::string &path, std::vector<std::string> cols)
{
  ohmdem::SignalTable::Options o;
  o.path = path;
  o.columns = std::move(cols);
  return o;
}

}  // namespace

TEST(SignalTable, ValuesReadBackBitForBit)
{
  const auto path = temp_path("roundtrip.txt");
  std::mt19937_64 rng(7);
  std::vector<std::vector<double>> written;
  {
    ohmdem::SignalTable t(options(path, {"time", "a", "b"}));
    // Random bit patterns over the whole finite range, plus the awkward ones.
    const std::vector<double> special = {0.0,
                                         -0.0,
                                         1e-310,
                                         -std::numeric_limits<double>::min(),
                                         std::numeric_limits<double>::max(),
                                         0.1,
                                         1.0 / 3.0,
                                         2.5e-7,
                                         -1.23456789012345678e300};
    for (int i = 0; i < 20000; ++i) {
      double v[3];
      for (double &x : v) {
        do {
          const std::uint64_t bits = rng();
          std::memcpy(&x, &bits, sizeof x);
        } while (!std::isfinite(x));
      }
      if (i < static_cast<int>(special.size())) v[1] = special[i];
      written.push_back({v[0], v[1], v[2]});
      t.row(v);
    }
  }
  const auto rows = read_rows(path);
  ASSERT_EQ(rows.size(), written.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(std::memcmp(&rows[i][k], &written[i][k], sizeof(double)), 0)
          << "row " << i << " value " << k << ": " << written[i][k];
    }
  std::filesystem::remove(path);
}

TEST(SignalTable, HeaderAndInfinity)
{
  const auto path = temp_path("header.txt");
  {
    ohmdem::SignalTable t(options(path, {"time", "R"}));
    const double r0[2] = {0.0, std::numeric_limits<double>::infinity()};  // R with no path
    const double r1[2] = {1e-6, 1.5};
    t.row(r0);
    t.row(r1);
  }
  EXPECT_EQ(slurp(path), "# time R\n0 inf\n1e-06 1.5\n");
  std::filesystem::remove(path);
}

TEST(SignalTable, SmallBufferFlushesInBlocks)
{
  const auto path = temp_path("blocks.txt");
  auto o = options(path, {"x"});
  o.buffer_bytes = 64;  // forces many writes
  {
    ohmdem::SignalTable t(o);
    for (int i = 0; i < 1000; ++i) {
      const double v = i;
      t.row(&v);
    }
    t.flush();
    EXPECT_EQ(read_rows(path).size(), 1000u);  // all there before the table closes
  }
  std::filesystem::remove(path);
}

TEST(SignalTable, AppendDropsRowsAfterTheRestartPoint)
{
  const auto path = temp_path("append.txt");
  {
    ohmdem::SignalTable t(options(path, {"time", "R"}));
    for (int i = 1; i <= 10; ++i) {
      const double v[2] = {i * 1e-6, 2.0 * i};
      t.row(v);
    }
  }
  // Continued from a restart written at t = 6e-6: rows 7..10 belong to the lost first try.
  auto o = options(path, {"time", "R"});
  o.append = true;
  o.resume_from = 6.5e-6;
  {
    ohmdem::SignalTable t(o);
    EXPECT_EQ(t.rows_dropped(), 4u);
    const double v[2] = {7e-6, -1.0};
    t.row(v);
  }
  const auto rows = read_rows(path);
  ASSERT_EQ(rows.size(), 7u);
  EXPECT_EQ(rows[5][0], 6e-6);
  EXPECT_EQ(rows[6][1], -1.0);
  EXPECT_EQ(slurp(path).rfind("# time R\n", 0), 0u);  // one header, at the top
  EXPECT_EQ(slurp(path).find("#", 1), std::string::npos);
  std::filesystem::remove(path);
}

TEST(SignalTable, AppendDropsALineCutByACrash)
{
  const auto path = temp_path("cut.txt");
  std::ofstream(path) << "# time R\n1e-06 2\n2e-06 4\n3e-06 6";  // no newline: cut mid-row
  auto o = options(path, {"time", "R"});
  o.append = true;
  o.resume_from = 1.0;  // nothing after the restart point, but the cut row must go
  {
    ohmdem::SignalTable t(o);
    EXPECT_EQ(t.rows_dropped(), 1u);
    const double v[2] = {3e-6, 6.5};
    t.row(v);
  }
  EXPECT_EQ(slurp(path), "# time R\n1e-06 2\n2e-06 4\n3e-06 6.5\n");
  std::filesystem::remove(path);
}

TEST(SignalTable, AppendToAnEmptyOrMissingFileWritesTheHeader)
{
  const auto path = temp_path("fresh.txt");
  std::filesystem::remove(path);
  auto o = options(path, {"t"});
  o.append = true;
  {
    ohmdem::SignalTable t(o);
    const double v = 1;
    t.row(&v);
  }
  EXPECT_EQ(slurp(path), "# t\n1\n");
  std::filesystem::remove(path);
}

TEST(SignalTable, AppendRefusesAnotherHeader)
{
  const auto path = temp_path("other.txt");
  std::ofstream(path) << "# time omega\n1e-06 2\n";
  auto o = options(path, {"time", "R"});
  o.append = true;
  try {
    ohmdem::SignalTable t(o);
    FAIL() << "expected an error";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("header '# time omega' is not this table's '# time R'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(slurp(path), "# time omega\n1e-06 2\n");  // untouched
  std::filesystem::remove(path);
}

TEST(SignalTable, UnwritableFileNamesTheFile)
{
  try {
    ohmdem::SignalTable t(options("/nonexistent-dir/signal.txt", {"x"}));
    FAIL() << "expected an error";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/signal.txt"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cannot be opened"), std::string::npos);
  }
}
