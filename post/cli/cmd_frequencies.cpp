// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post frequencies: kinematic defect frequencies from geometry and shaft speed.
#include <iostream>

#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"
#include "report/frequencies_report.h"

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

  out.write(frequencies_result(g, bc.geometry_source, f, harmonics));
  return 0;
}

}  // namespace ohmdem::post::cli
