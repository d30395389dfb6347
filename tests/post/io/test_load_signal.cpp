// SPDX-License-Identifier: GPL-2.0-or-later
// Loading a signal (post/io/load_signal.h): our signal.txt layout, the time window, a plain
// column that needs a rate, non-finite values counted only inside the window.
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
  expect_error([&] { load_signal(o, {}); }, "pass rate HZ");
  o.rate = 10;
  const Signal s = load_signal(o, {});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s.x[3], 4.0);
  EXPECT_EQ(s.rate, 10.0);
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

}  // namespace
}  // namespace ohmdem::post
