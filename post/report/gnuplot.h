// SPDX-License-Identifier: GPL-2.0-or-later
// PNG figures rendered by gnuplot (Debian gnuplot-nox, pngcairo terminal): the data go to
// temporary files, gnuplot runs as a child process (no shell), its messages are reported on
// failure. The gnuplot executable is $OHMDEM_GNUPLOT if set, else `gnuplot` from PATH.
#ifndef OHMDEM_POST_GNUPLOT_H
#define OHMDEM_POST_GNUPLOT_H

#include <cmath>
#include <string>
#include <vector>

namespace ohmdem::post {

struct PlotSeries {
  std::string title;
  std::vector<double> x, y;
  std::string style = "lines";  // gnuplot "with" style: lines, linespoints, points, impulses
};

struct PlotMarker {
  double x = 0;
  std::string label;
  std::string color = "#c0392b";
};

// A map drawn as an image under the series (e.g. a spectrogram): z[iy * x.size() + ix] at
// (x[ix], y[iy]) on a regular grid, colour scale labelled `zlabel`.
struct PlotImage {
  std::vector<double> x, y, z;
  std::string zlabel;
  bool empty() const { return z.empty(); }
};

struct Figure {
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
  std::vector<PlotMarker> markers;  // vertical dashed lines with rotated labels
  bool logy = false;
  double xmin = NAN, xmax = NAN;
  double ymin = NAN, ymax = NAN;  // vertical range (default: automatic)
  PlotImage image;                // optional, drawn first
  int width = 1100, height = 600;
};

// Throws Error if gnuplot is missing or fails (its message is included); the image is written
// beside png_path under a temporary name and renamed onto it on success, so a failure leaves
// no file (and an existing png_path unchanged).
void render_png(const Figure &fig, const std::string &png_path);

// The row in which each marker's label is drawn (0: just above the graph, 1: a label's length
// higher, ...): markers closer on the x axis than a label's width (a rotated line of text) get
// different heights, so that FTF's harmonics or 3xBPFO beside 2xBPFI do not overlap. Markers
// in [xmin, xmax] on a plot `width_px` wide; the result follows the order of `markers`.
std::vector<int> marker_label_rows(const std::vector<PlotMarker> &markers, double xmin, double xmax,
                                   double width_px);

// Where the markers' labels go: above the graph, whose top is at `graph_top` (screen
// fraction), each label centred on its line with its bottom at `label_bottom[i]` (screen
// fraction; the order of `markers`), rows `row_height` apart (a label's length): close markers'
// labels in different rows (marker_label_rows). Sizes in pixels of a `width` x `height` image.
struct MarkerLabelLayout {
  double graph_top = 1;
  std::vector<double> label_bottom;
  double row_height = 0;
};
constexpr int kMarkerFontPt = 8;
constexpr double kMarkerCharPx = 6;  // an 8-point character of the labels (pngcairo)
constexpr double kMarkerGapPx = 6;   // between the graph and a row, and between rows
constexpr double kTitlePx = 34;      // the title line above the labels
MarkerLabelLayout marker_label_layout(const std::vector<PlotMarker> &markers, double xmin,
                                      double xmax, int width, int height);

// The format of a linear axis's tick labels on [lo, hi] when %g's 6 digits would print several
// ticks alike (a span under about 1e-5 of the values), e.g. "%.8g"; "" otherwise.
std::string y_tick_format(double lo, double hi);

// Finds the gnuplot executable; "" if none.
std::string find_gnuplot();

// Reduces a long series for plotting: per bucket, the min and max (keeps spikes visible).
void decimate_minmax(const std::vector<double> &x, const std::vector<double> &y,
                     std::size_t max_points, std::vector<double> &xo, std::vector<double> &yo);

}  // namespace ohmdem::post

#endif
