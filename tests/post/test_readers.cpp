// SPDX-License-Identifier: GPL-2.0-or-later
// Readers on genuine LIGGGHTS 3.8 outputs (tests/post/data, made by data/in.fixtures), on our
// signal.txt layout, and on bad input (the library throws Error with a precise message).
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

using test::data;
using test::write_temp;

// Expects an Error whose message contains `part`.
template <class F>
void expect_error(F f, const std::string &part)
{
  try {
    f();
    ADD_FAILURE() << "no error, expected one containing '" << part << "'";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
        << "message: " << e.what() << "\nexpected to contain: " << part;
  }
}

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
               "choose a dump column with --column NAME|N (columns: c_cpl[1] c_cpl[2]");
}

TEST(Readers, DumpAsSignalNeedsTheStepLength)
{
  InputOptions o;
  o.files = {data("dump.atoms")};
  o.column = "vz";
  expect_error([&] { load_signal(o, {}); }, "--dt");
  RunMetadata m;
  m.path = "run.json";
  m.dt = 2.5e-5;
  const Signal s = load_signal(o, m);  // dt from the run's metadata
  EXPECT_NEAR(s.rate, 1 / (4000 * 2.5e-5), 1e-9);
}

std::string signal_txt(std::size_t n, const char *time_format, double dt, double t0 = 0.01)
{
  std::string text = "# time omega_cage fn_inner_mean fn_outer_mean n_contacts_race R n_masked\n";
  char buf[256];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) * dt;
    std::snprintf(buf, sizeof buf, time_format, t);
    text += buf;
    std::snprintf(buf, sizeof buf, " 198.05 34.1 24.6 26 %.10g %d\n", 1.39 + 0.001 * (i % 7),
                  static_cast<int>(i % 3 == 0));
    text += buf;
  }
  return text;
}

TEST(Readers, OurSignalTxtPicksRByDefault)
{
  // time printed with 6 significant digits at 1.5 us steps near 0.1 s: the printed steps
  // alternate 1 and 2 us; that is printing jitter, not non-uniform sampling
  const std::string p = write_temp("signal6.txt", signal_txt(5000, "%.6g", 1.5e-6, 0.1));
  InputOptions o;
  o.files = {p};
  const Signal s = load_signal(o, {});
  EXPECT_EQ(s.name, "R");
  EXPECT_EQ(s.size(), 5000u);
  EXPECT_NEAR(s.rate, 1 / 1.5e-6, 1);
  EXPECT_NEAR(s.x[3], 1.393, 1e-12);
  // a sample missing in the middle is non-uniform sampling
  std::string text = signal_txt(5000, "%.10g", 1e-6);
  const std::size_t a = text.find("\n0.012");
  const std::size_t b = text.find('\n', a + 1);
  text.erase(a, b - a);
  const std::string q = write_temp("signal_gap.txt", text);
  o.files = {q};
  expect_error([&] { load_signal(o, {}); }, "non-uniform time stamps");
  o.resample = true;
  const Signal r = load_signal(o, {});
  EXPECT_EQ(r.size(), 5000u);
  EXPECT_NEAR(r.rate, 1e6, 1e-3);
}

TEST(Readers, WindowSelectsTime)
{
  const std::string p = write_temp("signal_w.txt", signal_txt(1000, "%.10g", 1e-6));
  InputOptions o;
  o.files = {p};
  o.from = 0.0101;
  o.to = 0.0102;
  const Signal s = load_signal(o, {});
  EXPECT_EQ(s.size(), 101u);
  EXPECT_NEAR(s.t0, 0.0101, 1e-12);
}

TEST(Readers, PlainOneColumnNeedsRate)
{
  const std::string p = write_temp("plain.txt", "1.5\n-0.25\n3e-1\n+4\n");
  InputOptions o;
  o.files = {p};
  expect_error([&] { load_signal(o, {}); }, "pass --rate HZ");
  o.rate = 10;
  const Signal s = load_signal(o, {});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.x[3], 4.0);
  EXPECT_EQ(s.rate, 10.0);
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

TEST(Readers, NonFiniteValuesCountOnlyInsideTheWindow)
{
  // R = inf at step 0 of a thermo log (the first evaluation of a compute): fine when the window
  // starts later, an error naming the time and the line when the window holds it
  const std::string log =
      write_temp("inf_log.txt",
                 "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0)\ntimestep 1e-05\n"
                 "Step Atoms c_R\n0 10 inf\n100 10 1.5\n200 10 1.6\n300 10 1.55\n400 10 1.52\n"
                 "Loop time of 0.1 on 1 procs\n");
  InputOptions o;
  o.files = {log};
  o.column = "c_R";
  expect_error([&] { load_signal(o, {}); },
               "inf_log.txt:4: non-finite value (Inf) in column c_R at t = 0 s");
  o.from = 0.0005;
  const Signal s = load_signal(o, {});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.x.front(), 1.5);
  EXPECT_DOUBLE_EQ(s.t0, 0.001);
  // a column file: NaN after the window, and inside it
  const std::string table =
      write_temp("nan_late.txt", "# time R\n0 1\n0.001 2\n0.002 3\n0.003 nan\n");
  InputOptions t;
  t.files = {table};
  t.to = 0.0025;
  EXPECT_EQ(load_signal(t, {}).size(), 3u);
  t.to = 0.003;
  expect_error([&] { load_signal(t, {}); },
               "nan_late.txt:5: non-finite value (NaN) in column R at t = 0.003 s (inside the "
               "window)");
  // the time column places the window: it must be finite throughout
  const std::string nan_time =
      write_temp("nan_time.txt", "# time R\n0 1\n0.001 2\nnan 3\n0.003 4\n");
  InputOptions nt;
  nt.files = {nan_time};
  nt.to = 0.0015;
  expect_error([&] { load_signal(nt, {}); },
               "nan_time.txt:4: non-finite value (NaN) in column time");
  // with --rate, no time column: the sample's time is named
  const std::string plain = write_temp("inf_first.txt", "inf\n1\n2\n3\n");
  InputOptions r;
  r.files = {plain};
  r.rate = 10;
  r.from = 0.1;
  EXPECT_EQ(load_signal(r, {}).size(), 3u);
  r.from = NAN;
  expect_error([&] { load_signal(r, {}); }, "inf_first.txt:1: non-finite value (Inf)");
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
