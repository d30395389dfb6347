// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/table_select.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/text_scan.h"

namespace ohmdem::post {

namespace {

struct Condition {
  std::size_t column;
  bool equal;  // '=' or '!='
  std::string value;
};

const std::string &cell_text(const ColumnTable &t, std::size_t c, std::size_t r)
{
  static const std::string none;
  return c < t.text.size() && r < t.text[c].size() ? t.text[c][r] : none;
}

bool matches(const ColumnTable &t, const Condition &k, std::size_t r)
{
  const std::string &text = cell_text(t, k.column, r);
  if (!text.empty()) return text == k.value;
  const double v = t.columns[k.column][r];
  double want = 0;
  if (!std::isfinite(v) || !parse_double(k.value, want) || !std::isfinite(want)) return false;
  return std::fabs(v - want) <= 1e-12 * std::max(std::fabs(v), std::fabs(want));
}

}  // namespace

std::vector<std::size_t> select_rows(const ColumnTable &t, const std::string &where)
{
  std::vector<Condition> conds;
  std::size_t start = 0;
  while (start <= where.size() && !where.empty()) {
    std::size_t end = where.find(',', start);
    if (end == std::string::npos) end = where.size();
    const std::string item(trim(std::string_view(where).substr(start, end - start)));
    start = end + 1;
    if (item.empty()) continue;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw SettingError("option {select.where} expects COLUMN=VALUE or COLUMN!=VALUE, got '" +
                         item + "'");
    const bool negated = item[eq - 1] == '!';
    const std::string name(trim(std::string_view(item).substr(0, negated ? eq - 1 : eq)));
    if (name.empty())
      throw SettingError("option {select.where} expects COLUMN=VALUE or COLUMN!=VALUE, got '" +
                         item + "'");
    conds.push_back(
        {t.find(name), !negated, std::string(trim(std::string_view(item).substr(eq + 1)))});
  }
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    bool keep = true;
    for (const auto &k : conds) keep = keep && matches(t, k, r) == k.equal;
    if (keep) rows.push_back(r);
  }
  return rows;
}

std::vector<std::size_t> defined_rows(const ColumnTable &t, std::size_t column,
                                      const std::vector<std::size_t> &rows, std::size_t *undefined)
{
  std::vector<std::size_t> out;
  std::size_t skipped = 0;
  for (std::size_t r : rows) {
    const std::string &text = cell_text(t, column, r);
    const double v = t.columns.at(column).at(r);
    if (!text.empty())
      throw Error(t.source + ":" + std::to_string(t.line_of_row[r]) + ": column " +
                  t.names[column] + " is not numeric ('" + text + "')");
    if (std::isinf(v))
      throw Error(t.source + ":" + std::to_string(t.line_of_row[r]) +
                  ": non-finite value (Inf) in column " + t.names[column]);
    if (std::isnan(v)) {
      ++skipped;
      continue;
    }
    out.push_back(r);
  }
  if (undefined) *undefined = skipped;
  return out;
}

}  // namespace ohmdem::post
