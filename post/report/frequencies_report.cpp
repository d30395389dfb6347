// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/frequencies_report.h"

#include "bearing/defect_lines.h"
#include "core/text_scan.h"

namespace ohmdem::post {

Result frequencies_result(const BearingGeometry &g, const std::string &geometry_source,
                          const DefectFrequencies &f, int harmonics)
{
  Result r;
  r.meta = {
      {"bearing", g.name},
      {"geometry from", geometry_source},
      {"balls", std::to_string(g.nb)},
      {"ball diameter (m)", format_number(g.db)},
      {"pitch diameter (m)", format_number(g.dp)},
      {"contact angle (deg)", format_number(g.contact_angle_deg)},
      {"shaft frequency (Hz)", format_number(f.fr, 10)},
  };
  if (g.factors)  // the maker's multiples give the lines; a diameter of 0 is not published
    r.meta.emplace_back("factors (x fr)", "BPFO " + format_number(g.factors->bpfo) + ", BPFI " +
                                              format_number(g.factors->bpfi) + ", BSF " +
                                              format_number(g.factors->bsf) + ", FTF " +
                                              format_number(g.factors->ftf));
  r.table.columns = {"name", "harmonic", "frequency_Hz", "order_x_fr", "formula"};
  r.table.table_digits = 7;
  for (const DefectLine &line : defect_lines())
    for (int k = 1; k <= harmonics; ++k) {
      const double v = static_cast<double>(k) * line.of(f);
      r.table.rows.push_back({line.title, k, v, v / f.fr, line.formula});
    }
  // JSON: the bearing, then each line by key, its harmonics as arrays
  Json b = Json::object();
  b.set("name", g.name);
  b.set("nb", g.nb);
  b.set("db_m", g.db);
  b.set("dp_m", g.dp);
  b.set("contact_angle_deg", g.contact_angle_deg);
  r.json = Json::object();
  r.json.set("bearing", b);
  for (const DefectLine &line : defect_lines())
    r.json.set(std::string(line.key) + "_hz", line.of(f));
  if (harmonics > 1) {
    Json h = Json::object();
    for (const DefectLine &line : defect_lines()) {
      Json arr = Json::array();
      for (int k = 1; k <= harmonics; ++k) arr.push_back(static_cast<double>(k) * line.of(f));
      h.set(line.key, arr);
    }
    r.json.set("harmonics_hz", h);
  }
  return r;
}

}  // namespace ohmdem::post
