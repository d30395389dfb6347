// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/collect_report.h"

#include <algorithm>
#include <limits>

namespace ohmdem::post {

namespace {

Cell param_cell(const Json *v)
{
  if (!v) return Cell(std::numeric_limits<double>::quiet_NaN());
  if (v->is_number()) return Cell(v->number());
  if (v->is_string()) return Cell(v->string());
  return Cell(v->boolean() ? "true" : "false");
}

}  // namespace

Table collected_table(const std::vector<CollectedRun> &results,
                      const std::vector<std::string> &keys, const std::string &unit,
                      bool want_diagnosis)
{
  std::vector<std::string> fixed = {"run", "status", "t_start_s", "t_end_s", "n"};
  for (const auto &f : indicator_fields())
    fixed.push_back(f.dimensionless ? f.key : with_unit(f.key, unit));
  const bool any_duty =
      std::any_of(results.begin(), results.end(), [](const CollectedRun &r) { return r.has_duty; });
  if (any_duty) fixed.push_back("duty");
  if (want_diagnosis)
    for (const char *c : {"diag_defect", "diag_score", "diag_frequency_Hz", "diag_size_deg"})
      fixed.emplace_back(c);
  auto param_column = [&](const std::string &k) {
    return std::find(fixed.begin(), fixed.end(), k) != fixed.end() ? "param_" + k : k;
  };

  Table t;
  t.columns = {"run", "status"};
  for (const auto &k : keys) t.columns.push_back(param_column(k));
  t.columns.insert(t.columns.end(), fixed.begin() + 2, fixed.end());
  for (const auto &r : results) {
    std::vector<Cell> row{r.run, r.status};
    for (const auto &k : keys) row.push_back(param_cell(find_parameter(r.params, k)));
    row.emplace_back(r.t_start);
    row.emplace_back(r.t_end);
    row.emplace_back(r.ind.n);
    for (const auto &f : indicator_fields()) row.emplace_back(r.ind.*f.value);
    if (any_duty) row.emplace_back(r.duty);
    if (want_diagnosis) {
      const Diagnosis &d = r.diagnosis;
      row.emplace_back(d.defect);
      row.emplace_back(d.score);
      row.emplace_back(d.defect == "none" ? std::numeric_limits<double>::quiet_NaN()
                                          : d.frequency_hz);
      row.emplace_back(d.located.valid ? d.located.size_deg : std::numeric_limits<double>::quiet_NaN());
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace ohmdem::post
