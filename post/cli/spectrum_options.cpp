// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/spectrum_options.h"

#include <algorithm>
#include <climits>
#include <limits>

#include "cli/common.h"
#include "core/error.h"

namespace ohmdem::post::cli {

void add_spectrum_options(Args &a, const char *default_scale)
{
  a.section("Spectrum");
  a.option("--window", "NAME", window_names(), "hann");
  a.option("--detrend", "HOW", "none|mean|linear (per segment)", "mean");
  a.option("--scale", "KIND",
           "amplitude (a sine of amplitude A reads A) | power (A^2/2, sums to the mean square) "
           "| psd (unit^2/Hz)",
           default_scale);
  a.option("--segment", "N",
           "Welch averaging over segments of N samples (default: one segment, "
           "the whole signal)");
  a.option("--overlap", "F", "Welch segment overlap fraction", "0.5");
  a.option("--pad", "K", "zero padding: transform length K x segment", "1");
  a.option("--nfft", "N", "explicit transform length (>= segment)");
}

SpectrumOptions spectrum_options(const Args &a, std::size_t n, double rate)
{
  (void)rate;
  SpectrumOptions o;
  o.window = parse_window(a.get("--window"));
  o.detrend = parse_detrend(a.get("--detrend"));
  o.scaling = parse_scaling(a.get("--scale"));
  if (a.has("--segment")) {
    const long long seg = a.integer_in("--segment", 0, 4, LLONG_MAX, "a sample count");
    o.segment = static_cast<std::size_t>(seg);
    if (o.segment > n)
      throw Error("option --segment " + std::to_string(seg) + " exceeds the signal (" +
                  std::to_string(n) + " samples)");
  }
  o.overlap = a.number("--overlap", 0.5);
  o.pad = static_cast<std::size_t>(a.integer_in("--pad", 1, 1, 64));
  if (a.has("--nfft")) {
    // as --pad: at most 64 x the segment (a longer transform adds no information, only memory)
    const std::size_t seg = o.segment ? o.segment : n;
    const long long hi = 64 * static_cast<long long>(std::max<std::size_t>(seg, 4));
    const long long v = a.integer("--nfft", 0);
    if (v < 4 || v > hi)
      throw Error("option --nfft expects a transform length in 4.." + std::to_string(hi) +
                  " (at most 64 x the segment of " + std::to_string(seg) +
                  " samples, as --pad 64), got " + std::to_string(v));
    o.nfft = static_cast<std::size_t>(v);
  }
  return o;
}

void add_peak_options(Args &a)
{
  a.section("Peaks and rows");
  a.option("--peaks", "N", "number of peaks listed (largest first)", "10");
  a.option("--min-prominence", "DB", "peaks must stand this far above the local median floor", "6");
  a.flag("--no-interpolate", "report peak bins without interpolation");
  a.flag("--bins", "print every bin in [--fmin, --fmax] instead of the peaks");
  a.option("--fmin", "HZ", "lowest frequency reported", "0");
  a.option("--fmax", "HZ", "highest frequency reported (default: Nyquist)");
  a.option("--tolerance", "F",
           "relative tolerance for labelling peaks with defect frequencies, in (0, 0.2)", "0.02");
  a.option("--harmonics", "N", "harmonics of each defect frequency used for labels (1..50)", "5");
  a.flag("--fault-bands",
         "instead of the peaks, a fault-band table: per harmonic of fr, FTF, "
         "BPFO, BPFI, BSF, 2BSF the band +-tolerance, its peak and its power");
}

PeakOptions peak_options(const Args &a)
{
  PeakOptions p;
  p.max_peaks = peaks_option(a);
  p.min_prominence_db = a.number("--min-prominence", 6);
  p.interpolate = !a.has("--no-interpolate");
  p.fmin = a.number("--fmin", 0);
  p.fmax = a.number("--fmax", std::numeric_limits<double>::infinity());
  if (!(p.fmax > p.fmin)) throw Error("--fmax must exceed --fmin");
  return p;
}

Result spectrum_result(const Args &a, const Spectrum &s, MetaList meta, const std::string &unit,
                       const std::optional<DefectFrequencies> &kin, const char *what, bool bins)
{
  const PeakOptions po = peak_options(a);
  const double tol = tolerance_option(a);
  const int harmonics = harmonics_option(a, 5);
  const std::string vname = spectrum_value_name(s, unit);
  if (bins) return spectrum_bins_result(s, std::move(meta), vname, po.fmin, po.fmax);
  if (a.has("--fault-bands")) {
    if (!kin)
      throw Error("--fault-bands needs the bearing and the shaft speed (options or run.json)");
    return fault_band_result(fault_bands(s, *kin, harmonics, tol), std::move(meta), unit, tol);
  }
  return spectrum_peaks_result(find_peaks(s, po), std::move(meta), vname, what, po,
                               kin ? &*kin : nullptr, harmonics, tol);
}

}  // namespace ohmdem::post::cli
