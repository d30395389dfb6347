// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/stats_report.h"

#include "core/text_scan.h"

namespace ohmdem::post {

Result stats_result(const Signal &s, const std::vector<WindowIndicators> &windows,
                    const std::string &unit, bool remove_mean, bool windowed)
{
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
  return r;
}

}  // namespace ohmdem::post
