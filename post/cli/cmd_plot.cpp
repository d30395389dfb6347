// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post plot: PNG figures through gnuplot.
#include <algorithm>
#include <cmath>
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
#include "io/read_table.h"
#include "io/table_select.h"
#include "report/gnuplot.h"

namespace ohmdem::post::cli {

namespace {

// Defect-frequency markers up to fmax: harmonics 1..h of the fault lines (FTF, BPFO, BPFI, 2BSF).
std::vector<PlotMarker> defect_markers(const DefectFrequencies &k, int harmonics, double fmax)
{
  std::vector<PlotMarker> m;
  for (const DefectLine &line : defect_lines())
    if (line.fault_line)
      for (int h = 1; h <= harmonics; ++h)
        if (h * line.of(k) <= fmax)
          m.push_back({h * line.of(k), harmonic_label(h, line, false), line.color});
  return m;
}

Figure spectrum_figure(const Args &a, const Signal &s, const RunMetadata &meta, bool envelope_kind)
{
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<DefectFrequencies> kin;
  if (bc.geometry && bc.fr) kin = defect_frequencies(*bc.geometry, *bc.fr);
  const int harmonics = harmonics_option(a, 3);
  double fmax = a.number("--fmax", NAN);
  if (!std::isfinite(fmax))
    fmax = kin ? std::min(s.rate / 2, (harmonics + 0.5) * std::max(kin->bpfi, kin->bpfo) * 1.1)
               : s.rate / 2;
  std::vector<double> x = s.x;
  Figure fig;
  std::string what = "spectrum";
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
    what = "envelope spectrum (" + how + ")";
  }
  const SpectrumOptions so = spectrum_options(a, x.size(), s.rate);
  const Spectrum sp = spectrum(x, s.rate, so);
  PlotSeries ser;
  ser.title = what;
  const double fmin = a.number("--fmin", 0);
  for (std::size_t k = 0; k < sp.bins(); ++k) {
    const double f = sp.frequency(k);
    if (f < fmin || f > fmax) continue;
    ser.x.push_back(f);
    ser.y.push_back(sp.value[k]);
  }
  std::vector<double> xo, yo;
  decimate_minmax(ser.x, ser.y, 40000, xo, yo);
  ser.x = xo;
  ser.y = yo;
  fig.series.push_back(ser);
  if (kin) fig.markers = defect_markers(*kin, harmonics, fmax);
  const std::string unit = unit_of(a, s.name);
  fig.xlabel = "frequency (Hz)";
  fig.ylabel = std::string(scaling_name(sp.scaling)) + " of " + s.name +
               (unit.empty() ? "" : " (" + unit + scaling_unit(sp.scaling) + ")");
  fig.title = (envelope_kind ? "Envelope spectrum of " : "Spectrum of ") + s.name + ", " +
              window_name(sp.window) + " window, df " + format_number(sp.df, 4) + " Hz" +
              (kin ? ", " + bc.geometry->name + " at " + format_number(kin->fr, 5) + " Hz" : "");
  fig.xmin = fmin;
  fig.xmax = fmax;
  fig.logy = a.has("--logy");
  return fig;
}

// Issue 17: STFT magnitude (dB) as an image, the defect frequencies h x order x fr(t) of FTF,
// BPFO, BPFI and 2BSF as curves following the shaft speed (angle/speed column, else constant).
Figure spectrogram_figure(const Args &a, const Signal &s, const RunMetadata &meta)
{
  const BearingChoice bc = bearing_choice(a, meta);
  std::optional<ShaftAngle> sa = measured_shaft_angle(a, meta, s);
  if (!sa && bc.fr) sa = constant_shaft_angle(s, *bc.fr, bc.fr_source);
  const int harmonics = harmonics_option(a, 3);
  SpectrogramOptions so;
  if (a.has("--segment"))
    so.segment = static_cast<std::size_t>(
        a.integer_in("--segment", 0, 16, static_cast<long long>(s.size()), "a sample count"));
  so.window = parse_window(a.get("--window"));
  std::optional<DefectFrequencies> orders;
  if (bc.geometry) orders = defect_frequencies(*bc.geometry, 1.0);
  const double fr_max = sa ? sa->speed.max / (2 * kPi) : 0;
  so.fmax = a.number("--fmax", NAN);
  if (!std::isfinite(so.fmax))
    so.fmax = orders && sa ? std::min(s.rate / 2, (harmonics + 0.5) * 1.1 * fr_max *
                                                      std::max(orders->bpfi, orders->bpfo))
                           : s.rate / 2;
  so.fmin = a.number("--fmin", 0);
  const Spectrogram sg = spectrogram(s, so);
  Figure fig;
  PlotImage &im = fig.image;
  im.x = sg.t;
  im.y = sg.f;
  im.z = sg.db;
  fig.xlabel = "time (s)";
  fig.title = "Spectrogram of " + s.name + ", " + window_name(so.window) + " window, " +
              std::to_string(sg.segment) + " samples (df " + format_number(sg.df, 4) + " Hz)" +
              (sa && orders ? ", defect frequencies at the speed from " + sa->source : "");
  const std::string unit = unit_of(a, s.name);
  im.zlabel = "amplitude (dB re 1" + (unit.empty() ? std::string() : " " + unit) + ")";
  fig.ylabel = "frequency (Hz)";
  if (sa && orders) {
    // the fault lines h x order x fr(t), fr the mean shaft frequency over each segment
    const std::vector<double> fr = segment_shaft_hz(sg, sa->theta, s.rate);
    for (const DefectLine &line : defect_lines()) {
      if (!line.fault_line) continue;
      for (int h = 1; h <= harmonics; ++h) {
        PlotSeries ser;
        ser.title = harmonic_label(h, line, false);
        for (std::size_t c = 0; c < sg.t.size(); ++c) {
          const double y = h * line.of(*orders) * fr[c];
          if (y >= so.fmin && y <= so.fmax) {
            ser.x.push_back(im.x[c]);
            ser.y.push_back(y);
          }
        }
        if (!ser.x.empty()) fig.series.push_back(ser);
      }
    }
  }
  fig.xmin = im.x.front();
  fig.xmax = im.x.back();
  fig.ymin = im.y.front();
  fig.ymax = im.y.back();
  return fig;
}

Figure signal_figure(const Args &a, const Signal &s)
{
  std::vector<double> t(s.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = s.time(i);
  PlotSeries ser;
  ser.title = s.name;
  decimate_minmax(t, s.x, 20000, ser.x, ser.y);
  Figure fig;
  fig.series.push_back(ser);
  const std::string unit = unit_of(a, s.name);
  fig.xlabel = "time (s)";
  fig.ylabel = s.name + (unit.empty() ? "" : " (" + unit + ")");
  fig.title = s.name + "(t), " + format_number(s.rate) + " Hz, " + std::to_string(s.size()) +
              " samples" + (s.size() > 20000 ? " (min/max per pixel column)" : "");
  return fig;
}

Figure indicators_figure(const Args &a)
{
  if (a.positional().size() != 1) throw Error("plot --kind indicators reads one CSV or table file");
  const ColumnTable t = read_table(a.positional().front());
  if (!a.has("--x") || !a.has("--y"))
    throw Error("plot --kind indicators needs --x COLUMN and --y COLUMN[,COLUMN...] (columns: " +
                t.column_list() + ")");
  const std::size_t xc = t.find(a.get("--x"));
  // rows chosen by --where, then those with an x value (empty cells, e.g. a parameter a run
  // lacks or an undefined indicator, are left out and counted)
  const std::string where = a.get("--where");
  const std::vector<std::size_t> selected = select_rows(t, where);
  if (selected.empty())
    throw Error(t.source + ": no row satisfies --where " + where + " (" + std::to_string(t.rows()) +
                " rows)");
  std::size_t undefined = 0;
  const std::vector<std::size_t> with_x = defined_rows(t, xc, selected, &undefined);
  if (undefined)
    std::cout << undefined << " row(s) without a value of " << t.names[xc] << " left out\n";
  Figure fig;
  fig.xlabel = t.names[xc];
  std::string ys;
  for (const std::string &name : split_commas(a.get("--y"))) {
    const std::size_t yc = t.find(name);
    std::vector<std::size_t> order = defined_rows(t, yc, with_x, &undefined);
    if (undefined)
      std::cout << undefined << " row(s) without a value of " << t.names[yc] << " left out\n";
    if (order.empty())
      throw Error(t.source + ": column " + t.names[yc] + " has no value in the rows plotted");
    PlotSeries ser;
    ser.title = t.names[yc];
    ser.style = "linespoints pt 7 ps 1";
    std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
      return t.columns[xc][p] < t.columns[xc][q];
    });
    for (std::size_t i : order) {
      ser.x.push_back(t.columns[xc][i]);
      ser.y.push_back(t.columns[yc][i]);
    }
    fig.series.push_back(ser);
    ys += (ys.empty() ? "" : ", ") + t.names[yc];
  }
  if (fig.series.empty()) throw Error("option --y names no column");
  fig.ylabel = fig.series.size() == 1 ? ys : "indicator";
  fig.title = ys + " versus " + t.names[xc] + (where.empty() ? "" : " (" + where + ")");
  fig.logy = a.has("--logy");
  return fig;
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
  if (!a.parse(argv, std::cout)) return 0;
  if (!a.has("--output")) throw Error("plot: give the image file with --output FILE.png");
  const std::string kind =
      a.choice("--kind", {"signal", "spectrum", "envelope", "spectrogram", "indicators"});
  Figure fig;
  if (kind == "indicators") {
    fig = indicators_figure(a);
  } else if (kind == "spectrogram") {
    const RunMetadata meta = run_metadata(a);
    fig = spectrogram_figure(a, load_input(a, meta, 64), meta);
  } else {  // signal, spectrum or envelope
    const RunMetadata meta = run_metadata(a);
    const Signal s = load_input(a, meta, kind == "signal" ? 2 : 64);
    fig = kind == "signal" ? signal_figure(a, s) : spectrum_figure(a, s, meta, kind == "envelope");
  }
  if (a.has("--title")) fig.title = a.get("--title");
  const std::string size = a.get("--size");
  int w = 0, h = 0;
  char sep = 0;
  std::istringstream ss(size);
  if (!(ss >> w >> sep >> h) || sep != 'x' || w < 100 || h < 100 || w > 10000 || h > 10000)
    throw Error("option --size expects WIDTHxHEIGHT in pixels (100..10000), got '" + size + "'");
  fig.width = w;
  fig.height = h;
  render_png(fig, a.get("--output"));
  std::cout << "wrote " << a.get("--output") << "\n";
  return 0;
}

}  // namespace ohmdem::post::cli
