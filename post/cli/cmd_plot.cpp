// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post plot: PNG figures through gnuplot.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "bearing/defect_lines.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "cli/shaft_angle.h"
#include "cli/spectrum_options.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/envelope.h"
#include "dsp/spectrogram.h"
#include "dsp/stats.h"
#include "io/read_table.h"
#include "report/gnuplot.h"
#include "report/plot_figures.h"

namespace ohmdem::post::cli {

namespace {

Figure spectrum_plot(const Args &a, const Signal &s, const RunMetadata &meta, bool envelope_kind)
{
  const BearingChoice bc = bearing_choice(a, meta);
  SpectrumPlot p;
  if (bc.geometry && bc.fr) {
    p.kinematics = defect_frequencies(*bc.geometry, *bc.fr);
    p.bearing = bc.geometry->name;
  }
  const std::optional<DefectFrequencies> &kin = p.kinematics;
  p.harmonics = harmonics_option(a, 3);
  p.fmax = a.number("--fmax", NAN);
  if (!std::isfinite(p.fmax))
    p.fmax = kin ? std::min(s.rate / 2, (p.harmonics + 0.5) * std::max(kin->bpfi, kin->bpfo) * 1.1)
                 : s.rate / 2;
  std::vector<double> x = s.x;
  p.what = "spectrum";
  if (envelope_kind) {
    Band band{0, s.rate / 2};
    std::string how = "whole band";
    if (a.has("--band")) {
      band = band_option(a);
      how = "band " + format_number(band.lo) + "-" + format_number(band.hi) + " Hz";
    } else if (!a.has("--no-kurtogram")) {
      const double min_bw = kin ? defect_band_width(*kin, 5, s.rate) : s.rate / 256;
      const Kurtogram kg = kurtogram(x, s.rate, 7, min_bw);
      band = {kg.best.lo, kg.best.hi};
      how = "kurtogram band " + format_number(band.lo) + "-" + format_number(band.hi) + " Hz";
    }
    x = envelope(x, s.rate, band);
    p.what = "envelope spectrum (" + how + ")";
  }
  const SpectrumOptions so = spectrum_options(a, x.size(), s.rate);
  const Spectrum sp = spectrum(x, s.rate, so);
  p.fmin = a.number("--fmin", 0);
  p.quantity = s.name;
  p.unit = unit_of(a, s.name);
  p.envelope = envelope_kind;
  p.logy = a.has("--logy");
  if (meta.present()) {  // a simulated run: its numerical floor is drawn as such
    const Indicators ind = indicators(s.x);
    p.signal_mean = ind.mean;
    p.signal_std = ind.std;
  }
  return spectrum_figure(sp, p);
}

// The shaft speed from an angle/speed column, else constant (options, run.json); the fault
// lines follow it when the bearing is known.
Figure spectrogram_plot(const Args &a, const Signal &s, const RunMetadata &meta)
{
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<ShaftAngle> sa = measured_shaft_angle(a, meta, s);
  if (!sa && bc.fr) sa = constant_shaft_angle(s, *bc.fr, bc.fr_source);
  SpectrogramPlot p;
  p.harmonics = harmonics_option(a, 3);
  SpectrogramOptions so;
  if (a.has("--segment"))
    so.segment = static_cast<std::size_t>(
        a.integer_in("--segment", 0, 16, static_cast<long long>(s.size()), "a sample count"));
  so.window = parse_window(a.get("--window"));
  if (bc.geometry) p.orders = defect_frequencies(*bc.geometry, 1.0);
  const std::optional<DefectFrequencies> &orders = p.orders;
  const double fr_max = sa ? sa->speed.max / (2 * kPi) : 0;
  so.fmax = a.number("--fmax", NAN);
  if (!std::isfinite(so.fmax))
    so.fmax = orders && sa ? std::min(s.rate / 2, (p.harmonics + 0.5) * 1.1 * fr_max *
                                                      std::max(orders->bpfi, orders->bpfo))
                           : s.rate / 2;
  so.fmin = a.number("--fmin", 0);
  const Spectrogram sg = spectrogram(s, so);
  p.quantity = s.name;
  p.unit = unit_of(a, s.name);
  p.window = so.window;
  p.fmin = so.fmin;
  p.fmax = so.fmax;
  if (sa && orders) {
    // the fault lines h x order x fr(t), fr the mean shaft frequency over each segment
    p.shaft_hz = segment_shaft_hz(sg, sa->theta, s.rate);
    p.speed_source = sa->source;
  }
  return spectrogram_figure(sg, p);
}

Figure indicators_plot(const Args &a)
{
  if (a.positional().size() != 1) throw Error("plot --kind indicators reads one CSV or table file");
  const ColumnTable t = read_table(a.positional().front());
  if (!a.has("--x") || !a.has("--y"))
    throw Error("plot --kind indicators needs --x COLUMN and --y COLUMN[,COLUMN...] (columns: " +
                t.column_list() + ")");
  IndicatorsPlot p;
  p.x = a.get("--x");
  p.y = split_commas(a.get("--y"));
  p.where = a.get("--where");
  p.logy = a.has("--logy");
  return indicators_figure(t, p, [](const std::string &note) { std::cout << note << "\n"; });
}

// --size WxH
void set_size(const Args &a, Figure &fig)
{
  const std::string size = a.get("--size");
  int w = 0, h = 0;
  char sep = 0;
  std::istringstream ss(size);
  if (!(ss >> w >> sep >> h) || sep != 'x' || w < 100 || h < 100 || w > 10000 || h > 10000)
    throw Error("option --size expects WIDTHxHEIGHT in pixels (100..10000), got '" + size + "'");
  fig.width = w;
  fig.height = h;
}

// The options of plot (run_plot parses them).
void declare_options(Args &a)
{
  a.section("Figure");
  a.option("--kind", "KIND", "signal | spectrum | envelope | spectrogram | indicators", "signal");
  a.option("--output", "FILE", "the PNG to write (required)");
  a.option("--title", "TEXT", "figure title (default: describes the content)");
  a.option("--size", "WxH", "image size in pixels", "1100x600");
  a.flag("--logy", "logarithmic vertical axis");
  a.option("--fmin", "HZ", "lowest frequency shown", "0");
  a.option("--fmax", "HZ",
           "highest frequency shown (default: a little above the 3rd "
           "harmonic of BPFI/BPFO when the bearing is known, else Nyquist)");
  a.option("--harmonics", "N", "harmonics of each defect frequency marked (1..50)", "3");
  a.option("--band", "F1 F2", "envelope band (Hz) (default: the kurtogram's)", "", 2);
  a.flag("--no-kurtogram", "envelope of the whole band when no --band is given");
  a.option("--x", "COLUMN", "indicators: the swept parameter column");
  a.option("--y", "COL[,COL]", "indicators: the indicator column(s)");
  a.option("--where", "COL=VAL[,...]",
           "indicators: only the rows where every condition holds (COL=VALUE or COL!=VALUE; "
           "text or numbers), e.g. load=fixed");
  add_input_options(a);
  add_spectrum_options(a, "amplitude");
  add_bearing_options(a);
  add_shaft_angle_options(a);
  a.option("--unit", "UNIT", "unit of the signal for axis labels (default: ohm for R)");
}

// "healthy" for out/healthy/run.json (with its defect when it has one); "" without metadata.
std::string run_name(const RunMetadata &meta)
{
  if (!meta.present()) return "";
  const std::filesystem::path folder = std::filesystem::path(meta.path).parent_path();
  std::string name = folder.filename().string();
  if (name.empty() || name == ".") name = std::filesystem::absolute(folder).filename().string();
  if (meta.defect && *meta.defect != "none") name += " (" + *meta.defect + " defect)";
  return name;
}

// A logarithmic axis shows values > 0 only: a figure without one (an all-zero spectrum) is an
// error of its own, not gnuplot's "all points y value undefined".
void check_logy(const Figure &fig)
{
  if (!fig.logy || !fig.image.empty()) return;
  std::string names;
  for (const PlotSeries &s : fig.series) {
    for (double y : s.y)
      if (std::isfinite(y) && y > 0) return;
    names += (names.empty() ? "" : ", ") + s.title;
  }
  throw Error("plot --logy: no value of the figure is > 0 (" + names +
              ": all zero or negative); a logarithmic axis has nothing to draw: plot without "
              "--logy");
}

}  // namespace

int run_plot(const std::vector<std::string> &argv)
{
  Args a("plot",
         "--kind signal|spectrum|envelope|spectrogram|indicators --output FIG.png [options] FILE",
         "PNG figures rendered by gnuplot (pngcairo): the signal; its spectrum or envelope\n"
         "spectrum with the bearing's defect frequencies (FTF, BPFO, BPFI, 2xBSF and harmonics)\n"
         "marked; a spectrogram with them as curves following the shaft speed; indicators\n"
         "versus a swept parameter from a CSV/table (e.g. collected stats).");
  declare_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  if (!a.has("--output")) throw Error("plot: give the image file with --output FILE.png");
  refuse_input_as_output("--output", a.get("--output"), input_files(a));
  const std::string kind =
      a.choice("--kind", {"signal", "spectrum", "envelope", "spectrogram", "indicators"});
  Figure fig;
  std::string run;  // the run folder's name, when the input is a run's (its run.json)
  if (kind == "indicators") {
    fig = indicators_plot(a);
  } else if (kind == "spectrogram") {
    const RunMetadata meta = run_metadata(a);
    run = run_name(meta);
    fig = spectrogram_plot(a, load_input(a, meta, 64), meta);
  } else {  // signal, spectrum or envelope
    const RunMetadata meta = run_metadata(a);
    run = run_name(meta);
    const Signal s = load_input(a, meta, kind == "signal" ? 2 : 64);
    fig = kind == "signal" ? signal_figure(s, unit_of(a, s.name))
                           : spectrum_plot(a, s, meta, kind == "envelope");
  }
  // The title names the run (two runs' figures side by side are told apart).
  if (!run.empty()) fig.title = "run " + run + ": " + fig.title;
  if (a.has("--title")) fig.title = a.get("--title");
  set_size(a, fig);
  check_logy(fig);
  render_png(fig, a.get("--output"));
  std::cout << "wrote " << a.get("--output") << "\n";
  return 0;
}

}  // namespace ohmdem::post::cli
