// SPDX-License-Identifier: GPL-2.0-or-later
// NumPy .npy input: the fixtures of tests/post/make_npy_fixtures.py, written by numpy itself
// (record tables, 1-D and 2-D arrays in C and Fortran order, float32 and integers, format
// 2.0), read back value for value; the layouts numpy writes that we refuse, refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/load_signal.h"
#include "io/read_npy.h"
#include "io/read_table.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

std::string npy(const std::string &name)
{
  return test::data("npy/" + name);
}

// make_npy_fixtures.py's signal
double expected_x(int k)
{
  return 0.5 * std::sin(2 * kPi * 50 * (k / 1000.0)) + 0.01 * k;
}

std::string error_of(const std::function<void()> &f)
{
  try {
    f();
  } catch (const Error &e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(Npy, ReadsARecordTableByName)
{
  for (const char *name : {"table.npy", "table_v2.npy"}) {
    const ColumnTable t = read_npy(npy(name));
    ASSERT_EQ(t.names, (std::vector<std::string>{"time", "x", "n"})) << name;
    EXPECT_TRUE(t.has_header);
    ASSERT_EQ(t.rows(), 300u);
    for (int k = 0; k < 300; ++k) {
      EXPECT_EQ(t.columns[0][k], k / 1000.0);
      EXPECT_NEAR(t.columns[1][k], expected_x(k),
                  1e-14);  // numpy's sin and ours differ in the last bits
      EXPECT_EQ(t.columns[2][k], std::round(1000 * expected_x(k)));
    }
  }
}

TEST(Npy, ReadsPlainArraysInBothOrdersAndTypes)
{
  const ColumnTable c = read_npy(npy("c2d.npy")), f = read_npy(npy("f2d.npy"));
  ASSERT_EQ(c.cols(), 3u);
  ASSERT_EQ(f.cols(), 3u);
  EXPECT_FALSE(c.has_header);
  for (int k = 0; k < 300; ++k)
    for (std::size_t j = 0; j < 3; ++j) {
      const double want = j == 0 ? k / 1000.0 : (j == 1 ? 1 : 2) * expected_x(k);
      EXPECT_NEAR(c.columns[j][k], want, 1e-14);
      EXPECT_EQ(f.columns[j][k], c.columns[j][k]);  // the same numbers in the other order
    }
  const ColumnTable p = read_npy(npy("plain.npy")), i = read_npy(npy("int16.npy"));
  ASSERT_EQ(p.rows(), 300u);
  ASSERT_EQ(i.rows(), 300u);
  for (int k = 0; k < 300; ++k) {
    EXPECT_FLOAT_EQ(static_cast<float>(p.columns[0][k]), static_cast<float>(expected_x(k)));
    EXPECT_EQ(i.columns[0][k], std::round(1000 * expected_x(k)));
  }
}

TEST(Npy, RowsBeyondTheCountAreReadWithANote)
{
  const ColumnTable t = read_npy(npy("uncounted.npy"));
  EXPECT_EQ(t.rows(), 300u);
  ASSERT_FALSE(t.notes.empty());
  EXPECT_NE(t.notes.back().find("10 whole rows beyond the header's count"), std::string::npos);
}

// A record table cut inside the rows its header counts is refused with one error (numpy.load
// refuses it: "cannot reshape array of size 299 into shape (300,)"), no warning that a row was
// dropped before it; a row cut after the counted ones is dropped with a warning, the rest read.
TEST(Npy, CutInsideTheCountedRowsIsRefusedWithoutAWarning)
{
  std::vector<std::string> warnings;
  const auto saved = warning_sink();
  warning_sink() = [&](const std::string &m) { warnings.push_back(m); };
  const std::string whole = test::slurp(npy("table.npy"));
  const std::string cut = test::write_temp("cut_record.npy", whole.substr(0, whole.size() - 7));
  const std::string e = error_of([&] { read_npy(cut); });
  EXPECT_NE(e.find(cut + ": truncated: the header counts 300 rows, the file holds 299 whole rows "
                         "and 13 of the next row's 20 bytes"),
            std::string::npos)
      << e;
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  const std::string more = test::write_temp("uncounted_cut.npy", whole + whole.substr(200, 5));
  EXPECT_EQ(read_npy(more).rows(), 300u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("dropped the last row, cut before its end"), std::string::npos);
  warning_sink() = saved;
}

TEST(Npy, LoadSignalAndReadTableDetectTheFormat)
{
  InputOptions o;
  o.files = {npy("table.npy")};
  o.column = "x";
  const Signal s = load_signal(o, RunMetadata{});
  ASSERT_EQ(s.x.size(), 300u);
  EXPECT_DOUBLE_EQ(s.rate, 1000.0);
  EXPECT_NEAR(s.x[123], expected_x(123), 1e-14);
  EXPECT_EQ(read_table(npy("c2d.npy")).cols(), 3u);  // the text reader's entry point too
  o.files = {npy("plain.npy")};
  o.column.clear();
  o.rate = 1000;
  EXPECT_EQ(load_signal(o, RunMetadata{}).x.size(), 300u);
}

TEST(Npy, ClearErrors)
{
  EXPECT_NE(error_of([] { read_npy(npy("big.npy")); }).find("big-endian element type '>f8'"),
            std::string::npos);
  EXPECT_NE(
      error_of([] { read_npy(npy("complex.npy")); }).find("element type '<c16' is not supported"),
      std::string::npos);
  EXPECT_NE(
      error_of([] { read_npy(npy("cut.npy")); }).find("truncated: the header counts 300 rows"),
      std::string::npos);
  EXPECT_NE(error_of([] { read_npy(npy("subarray.npy")); }).find("sub-array"), std::string::npos);
  EXPECT_NE(error_of([] { read_npy(test::data("print.txt")); }).find("not an .npy file"),
            std::string::npos);
}

// Headers that lie about the file (hand-made: numpy writes none of them): a 4 GB header length,
// a shape of 1e20 rows, a shape of 1e18 columns. Each is refused by name before anything the
// header claims is allocated (the ASan build would catch an allocation of gigabytes).
TEST(Npy, LyingHeadersRefusedBeforeAllocating)
{
  auto file = [](const std::string &name, const std::string &dict, std::uint32_t len_field) {
    std::string s("\x93NUMPY\x02\x00", 8);
    for (int b = 0; b < 4; ++b) s += static_cast<char>((len_field >> (8 * b)) & 0xff);
    s += dict;
    s += std::string(64, '\0');  // some data bytes
    return test::write_temp(name, s);
  };
  const std::string good = "{'descr': '<f8', 'fortran_order': False, 'shape': (8,), }\n";
  EXPECT_NE(error_of([&] {
              read_npy(file("len4g.npy", good, 0xffffffffu));
            }).find("its length field says 4294967295 bytes"),
            std::string::npos);
  const std::string rows =
      "{'descr': '<f8', 'fortran_order': False, 'shape': (100000000000000000000,), }\n";
  EXPECT_NE(error_of([&] {
              read_npy(file("shape1e20.npy", rows, static_cast<std::uint32_t>(rows.size())));
            }).find("beyond 2^64"),
            std::string::npos);
  const std::string cols =
      "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 1000000000000000000), }\n";
  EXPECT_NE(error_of([&] {
              read_npy(file("cols1e18.npy", cols, static_cast<std::uint32_t>(cols.size())));
            }).find("more than the file's"),
            std::string::npos);
  const std::string many =
      "{'descr': '<f8', 'fortran_order': False, 'shape': (1000000000000,), }\n";
  EXPECT_NE(error_of([&] {
              read_npy(file("rows1e12.npy", many, static_cast<std::uint32_t>(many.size())));
            }).find("truncated: the header counts 1000000000000 rows"),
            std::string::npos);
}

// An element type that is not the data's: float64 data (8 values) under a '<i4' or '<f4'
// header of 8 elements is twice the bytes the header describes; refused, naming the type.
// The same bytes under the right header read back.
TEST(Npy, ElementTypeThatDoesNotMatchTheDataRefused)
{
  auto file = [](const std::string &name, const std::string &descr, const std::string &shape) {
    std::string dict = "{'descr': " + descr + ", 'fortran_order': False, 'shape': " + shape + ", }";
    dict.append((10 + dict.size() + 1 + 63) / 64 * 64 - 10 - dict.size() - 1, ' ');
    dict += '\n';
    std::string s("\x93NUMPY\x01\x00", 8);
    s += static_cast<char>(dict.size() & 0xff);
    s += static_cast<char>(dict.size() >> 8);
    s += dict;
    for (int k = 0; k < 8; ++k) {
      const double v = 1.25 * k;
      s.append(reinterpret_cast<const char *>(&v), sizeof v);
    }
    return test::write_temp(name, s);
  };
  EXPECT_EQ(read_npy(file("f8.npy", "'<f8'", "(8,)")).columns[0][3], 3.75);
  EXPECT_NE(error_of([&] {
              read_npy(file("i4.npy", "'<i4'", "(8,)"));
            }).find("element type '<i4' and shape give 32 data bytes, the file holds 64"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_npy(file("f4.npy", "'<f4'", "(8,)")); }).find("'<f4'"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              read_npy(file("rec_f4.npy", "[('t', '<f4'), ('R', '<f4')]", "(4,)"));
            }).find("does not describe the data"),
            std::string::npos);
}

}  // namespace ohmdem::post
