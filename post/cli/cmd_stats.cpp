// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post stats: the statistical indicators of the paper and more, over a window or per
// sliding window.
#include <cmath>
#include <iostream>

#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"
#include "dsp/stats.h"
#include "io/run_folders.h"

namespace ohmdem::post::cli {

int run_stats(const std::vector<std::string> &argv)
{
  Args a("stats", "[options] FILE...",
         "Statistical indicators of the signal over [--from, --to], or per sliding window.\n"
         "Moments are computed on the signal as given (the mean is not removed unless\n"
         "--remove-mean); kurtosis is Pearson's (3 for a normal law).");
  add_input_options(a);
  a.section("Indicators");
  a.option("--window-length", "S", "compute per sliding window of this length (s)");
  a.option("--step", "S", "hop between sliding windows (s) (default: the window length)");
  a.flag("--remove-mean", "subtract the mean of each window before computing");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  Signal s = load_input(a, meta, 2);
  Output out(a);
  const std::string unit = unit_of(a, s.name);
  const bool remove_mean = a.has("--remove-mean");

  const bool windowed = a.has("--window-length");
  std::size_t length = s.size(), hop = s.size();
  if (windowed) {
    const double len = a.number_in("--window-length", NAN, Range::above(0), "a length", "s");
    const double step = a.number_in("--step", len, Range::above(0), "a hop", "s");
    length = static_cast<std::size_t>(std::llround(len * s.rate));
    hop = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(step * s.rate)));
    if (length < 2 || length > s.size())
      throw Error("--window-length " + format_number(len) + " s gives " + std::to_string(length) +
                  " samples; it must hold 2 to " + std::to_string(s.size()) + " samples");
  }
  const std::vector<WindowIndicators> windows = sliding_indicators(s.x, length, hop, remove_mean);
  Result r;
  r.meta = s.meta;
  r.meta.emplace_back("mean removed", remove_mean ? "yes" : "no");
  r.meta.emplace_back("kurtosis", "Pearson (normal law = 3)");
  // one row per window
  r.table.columns = {"t_start_s", "t_end_s", "n"};
  for (const auto &f : indicator_fields())
    r.table.columns.push_back(f.dimensionless ? f.key : with_unit(f.key, unit));
  for (std::size_t w = 0; w < windows.size(); ++w) {
    const WindowIndicators &win = windows[w];
    std::vector<Cell> row{s.time(win.first), s.time(win.last - 1), win.ind.n};
    for (const auto &f : indicator_fields()) row.emplace_back(win.ind.*f.value);
    r.table.rows.push_back(row);
  }
  // one window reads better as one indicator a line, with its definition
  if (!windowed) {
    Table t;
    t.columns = {"indicator", "value", "definition"};
    for (const auto &f : indicator_fields())
      t.rows.push_back(
          {std::string(f.key) + (f.dimensionless || unit.empty() ? "" : " (" + unit + ")"),
           windows[0].ind.*f.value, f.definition});
    t.rows.push_back(
        {"samples", windows[0].ind.n,
         "from " + format_number(s.time(0)) + " to " + format_number(s.time(s.size() - 1)) + " s"});
    t.table_digits = 10;
    r.text.push_back({"", t});
  }
  // JSON: the window's indicators as fields, or the windows as an array
  auto window_json = [&](std::size_t w) {
    Json o = Json::object();
    o.set("t_start_s", s.time(windows[w].first));
    o.set("t_end_s", s.time(windows[w].last - 1));
    o.set("n", windows[w].ind.n);
    for (const auto &f : indicator_fields()) o.set(f.key, windows[w].ind.*f.value);
    return o;
  };
  r.json = windowed ? Json::object() : window_json(0);
  if (windowed) {
    Json arr = Json::array();
    for (std::size_t w = 0; w < windows.size(); ++w) arr.push_back(window_json(w));
    r.json.set("windows", arr);
  }
  r.json.set("unit", unit);
  r.json.set("mean_removed", remove_mean);
  r.json.set("meta", meta_json(r.meta));
  out.write(r);
  return 0;
}

}  // namespace ohmdem::post::cli
