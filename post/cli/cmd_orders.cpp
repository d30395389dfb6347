// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post orders: order spectrum and envelope order spectrum of a signal resampled at
// constant shaft-angle increments (order tracking), with the defect families marked in orders.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "bearing/defect_lines.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "cli/shaft_angle.h"
#include "cli/spectrum_options.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/envelope.h"
#include "dsp/order_tracking.h"
#include "dsp/peaks.h"
#include "report/orders_report.h"

namespace ohmdem::post::cli {

namespace {

MetaList speed_meta(const ShaftAngle &sa)
{
  const double hz = 1 / (2 * kPi);
  return {{"shaft angle", sa.source},
          {"shaft speed (Hz)",
           "mean " + format_number(sa.speed.mean * hz, 6) + ", " +
               format_number(sa.speed.min * hz, 6) + " to " + format_number(sa.speed.max * hz, 6) +
               " over 16 blocks (variation " + format_number(100 * sa.speed.variation, 3) + " %)"}};
}

// The options of orders (run_orders parses them).
void declare_options(Args &a)
{
  add_input_options(a);
  add_shaft_angle_options(a);
  add_bearing_options(a);
  a.section("Orders");
  a.option("--samples-per-rev", "S",
           "angle-domain samples per revolution (default: fs / mean shaft frequency, even); "
           "orders up to 0.4 S pass unchanged");
  a.flag("--envelope", "envelope order spectrum (band: --band, else --kurtogram, else all)");
  a.option("--band", "F1 F2", "envelope band (Hz, time domain)", "", 2);
  a.flag("--kurtogram", "choose the envelope band with the kurtogram");
  a.option("--levels", "N", "kurtogram levels (0..16)", "7");
  a.option("--show", "WHAT",
           "peaks (of the order spectrum) | bins (every bin) | resampled (the angle-domain "
           "signal)",
           "peaks");
  a.option("--peaks", "N", "number of peaks listed (largest first)", "10");
  a.option("--min-prominence", "DB", "peaks stand this far above the local median floor", "6");
  a.option("--order-min", "O", "lowest order reported", "0");
  a.option("--order-max", "O", "highest order reported (default: the flat band, 0.4 S)");
  a.option("--tolerance", "F",
           "relative tolerance for labelling peaks with defect orders, in (0, 0.2)", "0.02");
  a.option("--harmonics", "N", "harmonics of each defect order used for labels (1..50)", "5");
  a.flag("--keep-sliding", "analyse our runs' sliding phase too (default: from t_sliding_end)");
  add_spectrum_options(a, "amplitude");
  add_output_options(a);
}

// --envelope: `x` becomes the envelope in the band of --band or --kurtogram (else the whole
// band), noted in `m`. Returns what the spectrum is of.
std::string envelope_option(const Args &a, const Signal &s, const BearingChoice &bc,
                            const ShaftAngle &shaft, std::vector<double> &x, MetaList &m)
{
  if (a.has("--envelope")) {
    Band band{0, s.rate / 2};
    std::string how = "whole band";
    if (a.has("--band")) {
      if (a.has("--kurtogram")) throw Error("give either --band or --kurtogram, not both");
      band = band_option(a);
      how = "--band";
    } else if (a.has("--kurtogram")) {
      const int levels = levels_option(a);
      // bands wide enough to carry 5 harmonics of the defect frequencies at the top speed
      double min_bw = 0;
      if (bc.geometry) {
        min_bw = defect_band_width(defect_frequencies(*bc.geometry, shaft.speed.max / (2 * kPi)), 5,
                                   s.rate);
      }
      const Kurtogram kg = kurtogram(x, s.rate, levels, min_bw);
      band = {kg.best.lo, kg.best.hi};
      how = "kurtogram, spectral kurtosis " + format_number(kg.best.kurtosis, 4);
    }
    x = envelope(x, s.rate, band);
    m.emplace_back("envelope band (Hz)",
                   format_number(band.lo) + " to " + format_number(band.hi) + " (" + how + ")");
    return "envelope order spectrum";
  } else if (a.has("--band") || a.has("--kurtogram")) {
    throw Error("--band and --kurtogram choose the envelope band: add --envelope");
  }
  return "order spectrum";
}

}  // namespace

int run_orders(const std::vector<std::string> &argv)
{
  Args a("orders", "[options] FILE...",
         "Order tracking: the signal is resampled at constant increments of the shaft angle\n"
         "(band-limited Kaiser-windowed sinc interpolation whose cut-off follows the speed, so\n"
         "it also removes what would alias) and its spectrum taken with 'samples per revolution'\n"
         "as the rate: lines tied to the shaft stay sharp while the speed varies, at orders\n"
         "(cycles per revolution). The defect families are constant orders: FTF/fr, BPFO/fr,\n"
         "BPFI/fr, BSF/fr, 2BSF/fr. --envelope gives the envelope order spectrum (the envelope\n"
         "is formed in time, in a band in Hz, then resampled). The angle comes from an angle\n"
         "column, a speed column, our signal.txt's angle_inner, or a constant speed (--rpm, ...,\n"
         "run.json).");
  declare_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  const Signal s = load_input(a, meta, 64, !a.has("--keep-sliding"));
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<ShaftAngle> sa = measured_shaft_angle(a, meta, s);
  if (!sa) {
    if (!bc.fr)
      throw Error(
          "orders: no shaft angle: give --angle-column NAME, --speed-column NAME, or a "
          "constant speed (--rpm, --shaft-hz, --omega, --rpm-variable, run.json omega_inner)");
    sa = constant_shaft_angle(s, *bc.fr, bc.fr_source);
  }
  const std::string show = a.choice("--show", {"peaks", "bins", "resampled"});
  MetaList m = s.meta;
  const MetaList sm = speed_meta(*sa);
  m.insert(m.end(), sm.begin(), sm.end());

  std::vector<double> x = s.x;
  const std::string what = envelope_option(a, s, bc, *sa, x, m);
  const double spr = a.has("--samples-per-rev") ? a.number("--samples-per-rev")
                                                : default_samples_per_rev(s.rate, sa->speed.mean);
  const AngleResampled r = resample_by_angle(x, s.rate, sa->theta, spr);
  m.emplace_back("samples per revolution", format_number(spr, 8));
  m.emplace_back("resampling",
                 "Kaiser-windowed sinc (beta 10, 16 zero crossings), cut-off at order S/2 "
                 "at the local speed (or fs/2): flat to 1e-4 up to order " +
                     format_number(r.flat_order, 6) + ", >= 100 dB down above order " +
                     format_number(1.2 * spr / 2, 6));
  m.emplace_back("revolutions", format_number(r.revolutions(), 8) +
                                    " from t = " + format_number(s.t0 + r.t0, 8) + " s");
  const std::string unit = unit_of(a, s.name);
  Output out(a);
  if (show == "resampled") {
    Result rep;
    rep.meta = m;
    rep.table = resampled_table(r, spr, with_unit(s.name, unit));
    out.write(rep);
    return 0;
  }
  const SpectrumOptions so = spectrum_options(a, r.x.size(), spr);
  const Spectrum sp = spectrum(r.x, spr, so);
  m.emplace_back("order resolution", format_number(sp.df, 6) + " (samples per revolution / nfft)");
  std::optional<DefectFrequencies> orders;
  if (bc.geometry) {
    orders = defect_frequencies(*bc.geometry, 1.0);
    std::string list;
    for (const DefectLine &line : defect_lines())
      if (line.defect[0] != '\0')
        list += (list.empty() ? "" : ", ") + std::string(line.name) + " " +
                format_number(line.of(*orders), 6);
    m.emplace_back("defect orders (x fr)", list + " (" + bc.geometry->name + ")");
  }
  PeakOptions po;
  po.max_peaks = peaks_option(a);
  po.min_prominence_db = a.number("--min-prominence", 6);
  po.fmin = a.number("--order-min", 0);
  po.fmax = a.number("--order-max", r.flat_order);
  if (!(po.fmax > po.fmin)) throw Error("--order-max must exceed --order-min");
  const double tol = tolerance_option(a);
  const int harmonics = harmonics_option(a, 5);
  const std::string vname = with_unit(scaling_name(sp.scaling), unit);
  Result rep;
  rep.meta = m;
  const MetaList spm = spectrum_meta(sp, so.detrend);
  rep.meta.insert(rep.meta.end(), spm.begin(), spm.end());
  if (show == "bins") {
    rep.table = order_bins_table(sp, po.fmin, po.fmax, vname);
  } else {
    rep.meta.emplace_back(
        "peaks", what + ", largest first, prominence >= " + format_number(po.min_prominence_db) +
                     " dB over the local median, interpolated");
    rep.table =
        order_peaks_table(find_peaks(sp, po), vname, orders ? &*orders : nullptr, harmonics, tol);
  }
  out.write(rep);
  return 0;
}

}  // namespace ohmdem::post::cli
