// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/orders_report.h"

#include "bearing/defect_lines.h"
#include "core/constants.h"

namespace ohmdem::post {

Table resampled_table(const AngleResampled &r, double spr, const std::string &value_column)
{
  Table t;
  t.columns = {"revolution", "angle_rad", value_column};
  for (std::size_t k = 0; k < r.x.size(); ++k) {
    const double ang = r.theta0 + 2 * kPi * static_cast<double>(k) / spr;
    t.rows.push_back({ang / (2 * kPi), ang, r.x[k]});
  }
  t.table_digits = 10;
  return t;
}

Table order_bins_table(const Spectrum &sp, double lo, double hi, const std::string &value_column)
{
  Table t;
  t.columns = {"order", value_column};
  for (std::size_t k = 0; k < sp.bins(); ++k)
    if (sp.frequency(k) >= lo && sp.frequency(k) <= hi)
      t.rows.push_back({sp.frequency(k), sp.value[k]});
  t.table_digits = 8;
  return t;
}

Table order_peaks_table(const std::vector<Peak> &peaks, const std::string &value_column,
                        const DefectFrequencies *orders, int harmonics, double tolerance)
{
  Table t;
  t.columns = {"rank", "order", value_column, "prominence_dB"};
  if (orders) t.columns.push_back("label");
  int rank = 0;
  for (const Peak &p : peaks) {
    std::vector<Cell> row{++rank, p.frequency, p.value, p.prominence_db};
    if (orders) row.emplace_back(label_frequency(p.frequency, *orders, harmonics, tolerance));
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace ohmdem::post
