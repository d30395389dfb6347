// SPDX-License-Identifier: GPL-2.0-or-later
// The figures of ohmdem-post plot, made from what the library computed: the signal, its
// (envelope) spectrum with the bearing's defect frequencies marked, a spectrogram with them as
// curves following the shaft speed, indicators versus a swept parameter. report/gnuplot renders
// them.
#ifndef OHMDEM_POST_REPORT_PLOT_FIGURES_H
#define OHMDEM_POST_REPORT_PLOT_FIGURES_H

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "core/column_table.h"
#include "core/sampled_signal.h"
#include "dsp/spectrogram.h"
#include "dsp/spectrum.h"
#include "report/gnuplot.h"

namespace ohmdem::post {

// The signal against time (min/max per pixel column beyond 20000 samples).
Figure signal_figure(const Signal &s, const std::string &unit);

struct SpectrumPlot {
  std::string quantity, unit;  // the signal's name and unit ("" if unknown)
  std::string what;            // the series: "spectrum", "envelope spectrum (band ...)"
  bool envelope = false;       // an envelope spectrum
  double fmin = 0, fmax = 0;   // Hz shown
  std::optional<DefectFrequencies> kinematics;  // marked when known: harmonics 1..`harmonics`
  std::string bearing;                          // its bearing's name
  int harmonics = 3;                            // of FTF, BPFO, BPFI, 2BSF
  bool logy = false;
  // A simulated signal's mean and standard deviation (NaN: a measured record, or unknown): a
  // spread std/|mean| under kNumericalFloorSpread is the run's numerical floor, whose spectrum
  // is drawn on the scale of that floor (up to 1e-5 of the mean), not autoscaled into lines.
  double signal_mean = NAN, signal_std = NAN;
};
Figure spectrum_figure(const Spectrum &sp, const SpectrumPlot &p);

struct SpectrogramPlot {
  std::string quantity, unit;  // the signal's name and unit ("" if unknown)
  WindowKind window = WindowKind::Hann;
  double fmin = 0, fmax = 0;  // Hz shown
  // With the defect orders (fr = 1) and the mean shaft frequency over each segment, the fault
  // lines h x order x fr(t) (h = 1..harmonics), the speed from `speed_source`.
  std::optional<DefectFrequencies> orders;
  std::vector<double> shaft_hz;
  std::string speed_source;
  int harmonics = 3;
};
Figure spectrogram_figure(const Spectrogram &sg, const SpectrogramPlot &p);

struct IndicatorsPlot {
  std::string x;               // the swept parameter's column
  std::vector<std::string> y;  // the indicators' columns
  std::string where;           // rows kept (io/table_select.h), "" for all
  bool logy = false;
};
// Each `y` against `x` over the rows chosen by `where` that hold both values; `note` is told of
// the rows left out for an empty cell ("3 row(s) without a value of load left out").
Figure indicators_figure(const ColumnTable &t, const IndicatorsPlot &p,
                         const std::function<void(const std::string &)> &note);

}  // namespace ohmdem::post

#endif
