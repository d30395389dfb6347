// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post spectrum: one-sided spectrum and its peaks.
#include <iostream>

#include "cli/commands.h"
#include "cli/common.h"
#include "cli/spectrum_options.h"
#include "core/error.h"

namespace ohmdem::post::cli {

int run_spectrum(const std::vector<std::string> &argv)
{
  Args a("spectrum", "[options] FILE...",
         "One-sided spectrum of the signal (FFTW r2c): amplitude by default, a sine of\n"
         "amplitude A reading A at its peak once interpolated (window coherent gain corrected);\n"
         "power or PSD on request. Lists the largest peaks, labelled with the bearing's defect\n"
         "frequencies when a bearing and speed are known (options or run.json).");
  add_input_options(a);
  add_spectrum_options(a, "amplitude");
  add_peak_options(a);
  add_bearing_options(a);
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  const Signal s = load_input(a, meta, 4);
  const SpectrumOptions so = spectrum_options(a, s.size(), s.rate);
  const Spectrum sp = spectrum(s.x, s.rate, so);
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<DefectFrequencies> kin;
  if (bc.geometry && bc.fr) kin = defect_frequencies(*bc.geometry, *bc.fr);
  MetaList m = s.meta;
  const MetaList sm = spectrum_meta(sp, so.detrend);
  m.insert(m.end(), sm.begin(), sm.end());
  Output out(a);
  out.write(spectrum_result(a, sp, m, unit_of(a, s.name), kin, "spectrum peaks", a.has("--bins")));
  return 0;
}

}  // namespace ohmdem::post::cli
