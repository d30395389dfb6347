// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/plot_figures.h"

#include <algorithm>

#include "bearing/defect_lines.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/stats.h"
#include "io/table_select.h"

namespace ohmdem::post {

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

}  // namespace

Figure signal_figure(const Signal &s, const std::string &unit)
{
  std::vector<double> t(s.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = s.time(i);
  PlotSeries ser;
  ser.title = s.name;
  decimate_minmax(t, s.x, 20000, ser.x, ser.y);
  Figure fig;
  fig.series.push_back(ser);
  fig.xlabel = "time (s)";
  fig.ylabel = s.name + (unit.empty() ? "" : " (" + unit + ")");
  fig.title = s.name + "(t), " + format_number(s.rate) + " Hz, " + std::to_string(s.size()) +
              " samples" + (s.size() > 20000 ? " (min/max per pixel column)" : "");
  return fig;
}

Figure spectrum_figure(const Spectrum &sp, const SpectrumPlot &p)
{
  Figure fig;
  PlotSeries ser;
  ser.title = p.what;
  for (std::size_t k = 0; k < sp.bins(); ++k) {
    const double f = sp.frequency(k);
    if (f < p.fmin || f > p.fmax) continue;
    ser.x.push_back(f);
    ser.y.push_back(sp.value[k]);
  }
  std::vector<double> xo, yo;
  decimate_minmax(ser.x, ser.y, 40000, xo, yo);
  ser.x = xo;
  ser.y = yo;
  fig.series.push_back(ser);
  const auto &kin = p.kinematics;
  if (kin) fig.markers = defect_markers(*kin, p.harmonics, p.fmax);
  fig.xlabel = "frequency (Hz)";
  fig.ylabel = std::string(scaling_name(sp.scaling)) + " of " + p.quantity +
               (p.unit.empty() ? "" : " (" + p.unit + scaling_unit(sp.scaling) + ")");
  fig.title = (p.envelope ? "Envelope spectrum of " : "Spectrum of ") + p.quantity + ", " +
              window_name(sp.window) + " window, df " + format_number(sp.df, 4) + " Hz" +
              (kin ? ", " + p.bearing + " at " + format_number(kin->fr, 5) + " Hz" : "");
  fig.xmin = p.fmin;
  fig.xmax = p.fmax;
  fig.logy = p.logy;
  const double spread = p.signal_std / std::fabs(p.signal_mean);
  if (spread < kNumericalFloorSpread) {
    fig.ymax = kNumericalFloorSpread * std::fabs(p.signal_mean);
    if (!p.logy) fig.ymin = 0;
    fig.series.front().title += ": " + p.quantity + " at the run's numerical floor (std " +
                                format_number(spread, 2) +
                                " of its mean), axis up to 1e-5 of the mean";
  }
  return fig;
}

// The STFT magnitude (dB) as an image, the defect frequencies h x order x fr(t) of FTF,
// BPFO, BPFI and 2BSF as curves following the shaft speed.
Figure spectrogram_figure(const Spectrogram &sg, const SpectrogramPlot &p)
{
  const bool lines = p.orders && !p.speed_source.empty();
  Figure fig;
  PlotImage &im = fig.image;
  im.x = sg.t;
  im.y = sg.f;
  im.z = sg.db;
  fig.xlabel = "time (s)";
  fig.title = "Spectrogram of " + p.quantity + ", " + window_name(p.window) + " window, " +
              std::to_string(sg.segment) + " samples (df " + format_number(sg.df, 4) + " Hz)" +
              (lines ? ", defect frequencies at the speed from " + p.speed_source : "");
  im.zlabel = "amplitude (dB re 1" + (p.unit.empty() ? std::string() : " " + p.unit) + ")";
  fig.ylabel = "frequency (Hz)";
  if (lines) {
    for (const DefectLine &line : defect_lines()) {
      if (!line.fault_line) continue;
      for (int h = 1; h <= p.harmonics; ++h) {
        PlotSeries ser;
        ser.title = harmonic_label(h, line, false);
        for (std::size_t c = 0; c < sg.t.size(); ++c) {
          const double y = h * line.of(*p.orders) * p.shaft_hz[c];
          if (y >= p.fmin && y <= p.fmax) {
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

Figure indicators_figure(const ColumnTable &t, const IndicatorsPlot &p,
                         const std::function<void(const std::string &)> &note)
{
  const std::size_t xc = t.find(p.x);
  // rows chosen by `where`, then those with an x value (empty cells, e.g. a parameter a run
  // lacks or an undefined indicator, are left out and counted)
  const std::vector<std::size_t> selected = select_rows(t, p.where);
  if (selected.empty())
    throw SettingError(t.source + ": no row satisfies {select.where} " + p.where + " (" +
                       std::to_string(t.rows()) + " rows)");
  std::size_t undefined = 0;
  const std::vector<std::size_t> with_x = defined_rows(t, xc, selected, &undefined);
  auto left_out = [&](std::size_t column) {
    if (undefined)
      note(std::to_string(undefined) + " row(s) without a value of " + t.names[column] +
           " left out");
  };
  left_out(xc);
  Figure fig;
  fig.xlabel = t.names[xc];
  std::string ys;
  for (const std::string &name : p.y) {
    const std::size_t yc = t.find(name);
    std::vector<std::size_t> order = defined_rows(t, yc, with_x, &undefined);
    left_out(yc);
    if (order.empty())
      throw Error(t.source + ": column " + t.names[yc] + " has no value in the rows plotted");
    PlotSeries ser;
    ser.title = t.names[yc];
    ser.style = "linespoints pt 7 ps 1";
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      return t.columns[xc][i] < t.columns[xc][j];
    });
    for (std::size_t i : order) {
      ser.x.push_back(t.columns[xc][i]);
      ser.y.push_back(t.columns[yc][i]);
    }
    fig.series.push_back(ser);
    ys += (ys.empty() ? "" : ", ") + t.names[yc];
  }
  if (fig.series.empty()) throw SettingError("option {indicators.y} names no column");
  fig.ylabel = fig.series.size() == 1 ? ys : "indicator";
  fig.title = ys + " versus " + t.names[xc] + (p.where.empty() ? "" : " (" + p.where + ")");
  fig.logy = p.logy;
  return fig;
}

}  // namespace ohmdem::post
