// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post envelope: band-pass + Hilbert envelope, its spectrum, and the kurtogram.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "bearing/defect_lines.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "cli/spectrum_options.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/envelope.h"
#include "report/envelope_report.h"

namespace ohmdem::post::cli {

namespace {

// The options of envelope (run_envelope parses them).
void declare_options(Args &a)
{
  add_input_options(a);
  a.section("Envelope");
  a.option("--band", "F1 F2", "band-pass edges (Hz) (default: 0 to Nyquist)", "", 2);
  a.flag("--kurtogram", "choose the band with the fast kurtogram");
  a.option("--levels", "N", "kurtogram levels, up to 2^N bands (0..16)", "7");
  a.option("--min-bandwidth", "HZ",
           "narrowest kurtogram band (default: 5.5 x the largest defect frequency when bearing "
           "and speed are known, else fs/2^(levels+1))");
  a.option("--show", "WHAT",
           "peaks (of the envelope spectrum) | bins (envelope spectrum) | envelope (time "
           "series) | kurtogram (every band's spectral kurtosis)",
           "peaks");
  add_spectrum_options(a, "amplitude");
  add_peak_options(a);
  add_bearing_options(a);
  add_output_options(a);
}

}  // namespace

int run_envelope(const std::vector<std::string> &argv)
{
  Args a("envelope", "[options] FILE...",
         "Envelope analysis: the signal is band-passed (ideal filter in the frequency domain),\n"
         "its analytic signal formed with FFTW (Hilbert transform) and its magnitude taken;\n"
         "the envelope's spectrum (mean removed) shows repetition frequencies of impulses.\n"
         "Without --band the whole band is used, unless --kurtogram picks the band of largest\n"
         "spectral kurtosis.");
  declare_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  const Signal s = load_input(a, meta, 64);
  Output out(a);
  const std::string show = a.choice("--show", {"peaks", "bins", "envelope", "kurtogram"});
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<DefectFrequencies> kin;
  if (bc.geometry && bc.fr) kin = defect_frequencies(*bc.geometry, *bc.fr);
  MetaList m = s.meta;
  Band band{0, s.rate / 2};
  if (a.has("--band")) {
    band = band_option(a);
    m.emplace_back("band (Hz)", format_number(band.lo) + " to " + format_number(band.hi));
  }
  if (a.has("--kurtogram") || show == "kurtogram") {
    if (a.has("--band") && show != "kurtogram")
      throw Error("give either --band or --kurtogram, not both");
    const int levels = levels_option(a);
    // bands wide enough to carry 5 harmonics of the defect frequencies when they are known
    const double min_bw = a.number("--min-bandwidth", kin ? defect_band_width(*kin, 5, s.rate) : 0);
    std::vector<double> x = s.x;
    const Kurtogram kg = kurtogram(x, s.rate, levels, min_bw);
    if (show == "kurtogram") {
      out.write(kurtogram_result(kg, m));
      return 0;
    }
    band = {kg.best.lo, kg.best.hi};
    m.emplace_back("band (Hz)", format_number(band.lo) + " to " + format_number(band.hi) +
                                    " (kurtogram, spectral kurtosis " +
                                    format_number(kg.best.kurtosis, 4) + ")");
    m.emplace_back("band kurtosis significant", kurtogram_significance(kg));
  }
  const std::vector<double> env = envelope(s.x, s.rate, band);
  const std::string unit = unit_of(a, s.name);
  if (show == "envelope") {
    out.write(envelope_result(s, env, unit, m));
    return 0;
  }
  const SpectrumOptions so = spectrum_options(a, env.size(), s.rate);
  const Spectrum sp = spectrum(env, s.rate, so);
  const MetaList sm = spectrum_meta(sp, so.detrend);
  m.insert(m.end(), sm.begin(), sm.end());
  out.write(spectrum_result(a, sp, m, unit, kin, "envelope spectrum peaks",
                            show == "bins" || a.has("--bins")));
  return 0;
}

}  // namespace ohmdem::post::cli
