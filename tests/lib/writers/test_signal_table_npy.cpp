// SPDX-License-Identifier: GPL-2.0-or-later
// The .npy format of the signal table writer: the header layout numpy expects (magic,
// version, 64-byte alignment, the row count rewritten in place), the rows as raw float64
// records, and continuing a file after a restart (rows after the restart point dropped, a row
// cut by a crash dropped, another header refused). numpy itself reads these files in
// tests/decks/signal_tests.py (npy_equal, npy_restart_append).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "temp_dir.h"
#include "writers/npy_header.h"
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

ohmdem::SignalTable::Options npy(const std::string &path, std::vector<std::string> cols)
{
  ohmdem::SignalTable::Options o;
  o.path = path;
  o.columns = std::move(cols);
  o.format = ohmdem::SignalTable::Format::Npy;
  return o;
}

// The header length and the float64 values after it.
std::pair<std::size_t, std::vector<double>> data_of(const std::string &bytes)
{
  const std::size_t len = static_cast<unsigned char>(bytes[8]) |
                          (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
  const std::size_t start = 10 + len;
  std::vector<double> v((bytes.size() - start) / 8);
  std::memcpy(v.data(), bytes.data() + start, v.size() * 8);
  return {start, v};
}

void write_rows(const std::string &path, int n)
{
  ohmdem::SignalTable t(npy(path, {"time", "R"}));
  for (int i = 1; i <= n; ++i) {
    const double v[2] = {i * 1e-6, 2.0 * i};
    t.row(v);
  }
}

}  // namespace

TEST(NpyHeader, LayoutNumpyExpects)
{
  const auto h = ohmdem::npy_table_header({"time", "R"}, 12);
  ASSERT_GE(h.bytes.size(), 64u);
  EXPECT_EQ(h.bytes.substr(0, 6), "\x93NUMPY");
  EXPECT_EQ(h.bytes[6], '\x01');  // version 1.0
  EXPECT_EQ(h.bytes[7], '\x00');
  EXPECT_EQ(h.bytes.size() % 64, 0u);  // numpy aligns the data to 64 bytes
  const std::size_t len = static_cast<unsigned char>(h.bytes[8]) |
                          (static_cast<std::size_t>(static_cast<unsigned char>(h.bytes[9])) << 8);
  EXPECT_EQ(len + 10, h.bytes.size());
  EXPECT_EQ(h.bytes.back(), '\n');
  EXPECT_NE(h.bytes.find("{'descr': [('time', '<f8'), ('R', '<f8')], 'fortran_order': False, "
                         "'shape': ("),
            std::string::npos);
  EXPECT_EQ(h.bytes.substr(h.rows_offset, h.rows_width), ohmdem::npy_rows_field(12));
  EXPECT_EQ(h.bytes.substr(h.rows_offset + h.rows_width, 3), ",),");
  // The count field has the same width whatever the count: it is rewritten in place.
  EXPECT_EQ(ohmdem::npy_rows_field(0).size(), ohmdem::npy_rows_field(UINT64_MAX).size());
}

TEST(NpyHeader, ManyColumnsGoToVersion2)
{
  std::vector<std::string> cols;
  for (int i = 0; i < 4000; ++i) cols.push_back("column_" + std::to_string(i));
  const auto h = ohmdem::npy_table_header(cols, 0);
  EXPECT_EQ(h.bytes[6], '\x02');  // 2.0: a 4-byte header length
  EXPECT_EQ(h.bytes.size() % 64, 0u);
}

TEST(NpyHeader, RefusesNamesThatBreakTheHeader)
{
  EXPECT_THROW(ohmdem::npy_table_header({"it's"}, 0), std::invalid_argument);
  EXPECT_THROW(ohmdem::npy_table_header({"a\\b"}, 0), std::invalid_argument);
  EXPECT_THROW(ohmdem::npy_table_header({""}, 0), std::invalid_argument);
  EXPECT_THROW(ohmdem::npy_table_header({}, 0), std::invalid_argument);
}

TEST(NpyTable, RowsAreTheValuesBitForBitAndCounted)
{
  const auto path = temp_path("rows.npy");
  write_rows(path, 5);
  const std::string bytes = slurp(path);
  const auto h = ohmdem::npy_table_header({"time", "R"}, 5);
  EXPECT_EQ(bytes.substr(0, h.bytes.size()), h.bytes);  // header with the row count 5
  const auto [start, v] = data_of(bytes);
  ASSERT_EQ(v.size(), 10u);
  for (int i = 1; i <= 5; ++i) {
    EXPECT_EQ(v[2 * (i - 1)], i * 1e-6);
    EXPECT_EQ(v[2 * (i - 1) + 1], 2.0 * i);
  }
  std::filesystem::remove(path);
}

TEST(NpyTable, AppendDropsRowsAfterTheRestartPointAndACutRow)
{
  const auto path = temp_path("append.npy");
  write_rows(path, 10);
  // A crash cut a row mid-way: 3 stray bytes at the end.
  std::ofstream(path, std::ios::binary | std::ios::app) << "abc";
  auto o = npy(path, {"time", "R"});
  o.append = true;
  o.resume_from = 6.5e-6;  // restart written at t = 6e-6: rows 7..10 and the cut row go
  {
    ohmdem::SignalTable t(o);
    EXPECT_EQ(t.rows_dropped(), 5u);
    const double v[2] = {7e-6, -1.0};
    t.row(v);
  }
  const std::string bytes = slurp(path);
  const auto h = ohmdem::npy_table_header({"time", "R"}, 7);
  EXPECT_EQ(bytes.substr(0, h.bytes.size()), h.bytes);  // count updated to 7
  const auto [start, v] = data_of(bytes);
  ASSERT_EQ(v.size(), 14u);
  EXPECT_EQ(v[10], 6e-6);
  EXPECT_EQ(v[12], 7e-6);
  EXPECT_EQ(v[13], -1.0);
  std::filesystem::remove(path);
}

TEST(NpyTable, AppendRefusesAnotherHeaderAndLeavesTheFile)
{
  const auto path = temp_path("other.npy");
  write_rows(path, 3);
  const std::string before = slurp(path);
  auto o = npy(path, {"time", "omega"});
  o.append = true;
  try {
    ohmdem::SignalTable t(o);
    FAIL() << "expected an error";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("('R', '<f8')"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is not this table's"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), before);
  std::filesystem::remove(path);
}

TEST(NpyTable, AppendRefusesATextFile)
{
  const auto path = temp_path("text.npy");
  std::ofstream(path) << "# time R\n1e-06 2\n";
  auto o = npy(path, {"time", "R"});
  o.append = true;
  EXPECT_THROW(ohmdem::SignalTable t(o), std::runtime_error);
  std::filesystem::remove(path);
}
