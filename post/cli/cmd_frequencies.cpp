// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post frequencies: kinematic defect frequencies from geometry and shaft speed.
#include <iostream>

#include "bearing/defect_lines.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"

namespace ohmdem::post::cli {

int run_frequencies(const std::vector<std::string> &argv)
{
  Args a("frequencies",
         "--bearing NAME [--catalog DIR] | --nb N --db M --dp M [--beta DEG] | --factors LIST  "
         "--rpm RPM | --shaft-hz HZ | --omega RAD/S",
         "Kinematic frequencies of a bearing with a rotating inner ring and a fixed outer ring\n"
         "(Harris): FTF = fr/2 (1 - d/D cos b), BPFO = Nb FTF, BPFI = Nb fr/2 (1 + d/D cos b),\n"
         "BSF = D/(2d) fr (1 - (d/D cos b)^2); a ball defect strikes the races at 2 BSF.\n"
         "--bearing takes a name of the bearing catalog (doc/bearing_catalog.md); the pitch\n"
         "diameter of a catalog bearing is Dpw or (Dext + Dinn)/2, as in the deck. --factors\n"
         "BPFO,BPFI,BSF,FTF: the maker's multiples of fr, for a bearing in no catalog.");
  add_bearing_options(a);
  a.option("--harmonics", "N", "also list harmonics 2..N of each frequency (1..50)", "1");
  a.option("--metadata", "FILE", "read bearing and speed from a run.json");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  if (!a.positional().empty())
    throw Error("frequencies: unexpected argument '" + a.positional().front() + "'");
  const RunMetadata meta =
      a.has("--metadata") ? read_run_metadata(a.get("--metadata")) : RunMetadata{};
  const BearingChoice bc = bearing_choice(a, meta);
  if (!bc.geometry)
    throw Error("frequencies: give a bearing (--bearing NAME, --nb --db --dp, or --factors)");
  if (!bc.fr) throw Error("frequencies: give the shaft speed (--rpm, --shaft-hz or --omega)");
  const int harmonics = harmonics_option(a, 1);
  const BearingGeometry &g = *bc.geometry;
  const DefectFrequencies f = defect_frequencies(g, *bc.fr);
  Output out(a);

  Result r;
  r.meta = {
      {"bearing", g.name},
      {"geometry from", bc.geometry_source},
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
  out.write(r);
  return 0;
}

}  // namespace ohmdem::post::cli
