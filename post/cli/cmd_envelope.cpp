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

namespace ohmdem::post::cli {

namespace {

// Issue 17: whether the best band's spectral kurtosis is more than a Gaussian record reaches.
std::string significance(const Kurtogram &kg)
{
  return std::string(kg.significant ? "yes" : "no") + " (threshold " +
         format_number(kg.threshold, 4) + ": a Gaussian record's best band exceeds it with " +
         "probability " + format_number(kg.alpha) + "; " + std::to_string(kg.best.samples) +
         " envelope samples, " + std::to_string(kg.cells.size()) + " bands searched)";
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
      Result r;
      r.meta = m;
      r.meta.emplace_back("spectral kurtosis",
                          "E|c|^4/(E|c|^2)^2 - 2 of the band's complex "
                          "envelope (0 for Gaussian noise)");
      r.meta.emplace_back("best band (Hz)",
                          format_number(kg.best.lo) + " to " + format_number(kg.best.hi));
      r.meta.emplace_back("band kurtosis significant", significance(kg));
      r.table.columns = {"bands", "f_low_Hz", "f_high_Hz", "center_Hz", "spectral_kurtosis"};
      for (const auto &c : kg.cells)
        r.table.rows.push_back({c.bands, c.lo, c.hi, (c.lo + c.hi) / 2, c.kurtosis});
      out.write(r);
      return 0;
    }
    band = {kg.best.lo, kg.best.hi};
    m.emplace_back("band (Hz)", format_number(band.lo) + " to " + format_number(band.hi) +
                                    " (kurtogram, spectral kurtosis " +
                                    format_number(kg.best.kurtosis, 4) + ")");
    m.emplace_back("band kurtosis significant", significance(kg));
  }
  const std::vector<double> env = envelope(s.x, s.rate, band);
  const std::string unit = unit_of(a, s.name);
  if (show == "envelope") {
    Result r;
    r.meta = m;
    r.meta.emplace_back("envelope", "|analytic signal| of the band-passed signal");
    r.table.columns = {"time_s", with_unit("envelope", unit)};
    for (std::size_t i = 0; i < env.size(); ++i) r.table.rows.push_back({s.time(i), env[i]});
    r.table.table_digits = 10;
    out.write(r);
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
