// SPDX-License-Identifier: GPL-2.0-or-later
// The figures of plot, made from what the library computed: indicators sorted by the swept
// parameter with the rows left out told, their errors in settings; the spectrogram's fault lines
// only with the shaft speed; the defect lines' labels above the graph; ticks told apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "core/error.h"
#include "io/read_table.h"
#include "report/gnuplot.h"
#include "report/plot_figures.h"
#include "temp_dir.h"

namespace ohmdem::post {
namespace {

ColumnTable sweep()
{
  const std::string path = ohmdem::test::temp_path("plot_figures_sweep.csv");
  std::ofstream(path) << "load,rms,kind\n2,0.2,a\n1,0.1,a\n,0.3,a\n3,0.4,b\n";
  return read_table(path);
}

TEST(PlotFigures, IndicatorsSortedByTheParameterRowsLeftOutTold)
{
  IndicatorsPlot p;
  p.x = "load";
  p.y = {"rms"};
  p.where = "kind=a";
  std::vector<std::string> notes;
  const Figure fig =
      indicators_figure(sweep(), p, [&](const std::string &n) { notes.push_back(n); });
  ASSERT_EQ(fig.series.size(), 1u);
  EXPECT_EQ(fig.series[0].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(fig.series[0].y, (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(fig.title, "rms versus load (kind=a)");
  EXPECT_EQ(notes, (std::vector<std::string>{"1 row(s) without a value of load left out"}));
}

TEST(PlotFigures, IndicatorsErrorsNameSettings)
{
  IndicatorsPlot p;
  p.x = "load";
  p.y = {"rms"};
  p.where = "kind=c";
  const auto ignore = [](const std::string &) {};
  try {
    indicators_figure(sweep(), p, ignore);
    FAIL() << "no row selected, no error";
  } catch (const SettingError &e) {
    EXPECT_NE(e.text().find("no row satisfies {select.where} kind=c (4 rows)"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no row satisfies where kind=c"), std::string::npos);
  }
  p.where.clear();
  p.y.clear();
  try {
    indicators_figure(sweep(), p, ignore);
    FAIL() << "no indicator column, no error";
  } catch (const SettingError &e) {
    EXPECT_EQ(e.text(), "option {indicators.y} names no column");
  }
}

TEST(PlotFigures, SpectrogramFaultLinesFollowTheSpeedWhenKnown)
{
  Spectrogram sg;
  sg.segment = 64;
  sg.df = 10;
  sg.t = {0.1, 0.2};
  sg.f = {0, 100, 200};
  sg.db.assign(6, -20);
  SpectrogramPlot p;
  p.quantity = "R";
  p.unit = "ohm";
  p.fmin = 0;
  p.fmax = 1e6;
  p.harmonics = 2;
  p.orders = defect_frequencies({"custom", 9, 0.01, 0.05, 0, std::nullopt}, 1.0);
  const Figure none = spectrogram_figure(sg, p);  // no speed: the image alone
  EXPECT_TRUE(none.series.empty());
  EXPECT_EQ(none.image.zlabel, "amplitude (dB re 1 ohm)");
  EXPECT_EQ(none.title.find("defect frequencies"), std::string::npos);
  p.shaft_hz = {10, 20};
  p.speed_source = "angle column";
  const Figure lines = spectrogram_figure(sg, p);
  ASSERT_EQ(lines.series.size(), 8u);  // FTF, BPFO, BPFI, 2BSF, harmonics 1 and 2
  for (const PlotSeries &s : lines.series) {
    ASSERT_EQ(s.y.size(), 2u);
    EXPECT_DOUBLE_EQ(s.y[1], 2 * s.y[0]);  // h x order x fr(t), fr doubling
  }
  EXPECT_NE(lines.title.find("defect frequencies at the speed from angle column"),
            std::string::npos);
}

}  // namespace
// The defect lines of the demo's spectra (the 6208 at 500 rad/s: FTF 31.516 Hz, 2BSF 366.18,
// BPFO 409.71, BPFI 624.80 Hz; `ohmdem-post frequencies --bearing machado2014 --omega 500`) on
// 0..2400 Hz: FTF's harmonics 12 px apart and 3xBPFO 20 Hz from 2xBPFI get labels at different
// heights; labels at one height are a label's width apart.
TEST(PlotFigures, MarkerLabelsOfCloseLinesDoNotOverlap)
{
  std::vector<PlotMarker> m;
  for (int h = 1; h <= 3; ++h) {
    m.push_back({h * 31.5158, std::to_string(h) + "xFTF"});
    m.push_back({h * 366.184, std::to_string(h) + "x2BSF"});
    m.push_back({h * 409.706, std::to_string(h) + "xBPFO"});
    m.push_back({h * 624.801, std::to_string(h) + "xBPFI"});
  }
  const double width = 0.85 * 1100;  // as render_png
  const std::vector<int> rows = marker_label_rows(m, 0, 2400, width);
  ASSERT_EQ(rows.size(), m.size());
  auto px = [&](std::size_t i) { return m[i].x / 2400 * width; };
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = i + 1; j < m.size(); ++j)
      if (rows[i] == rows[j]) {
        EXPECT_GE(std::fabs(px(i) - px(j)), 14) << m[i].label << " and " << m[j].label;
      }
  EXPECT_NE(rows[0], rows[4]);   // FTF, 2xFTF
  EXPECT_NE(rows[10], rows[7]);  // 3xBPFO, 2xBPFI
  EXPECT_EQ(rows[3], 0);         // BPFI alone: at the top, as before
}

// The labels stand above the graph in rows a label's length apart: every label's bottom lies
// above the graph's top, rows do not overlap, and the title keeps its line at the top.
TEST(PlotFigures, MarkerLabelsStandAboveTheGraph)
{
  std::vector<PlotMarker> m;
  for (int h = 1; h <= 3; ++h) {
    m.push_back({h * 31.5158, std::to_string(h) + "xFTF"});
    m.push_back({h * 409.706, std::to_string(h) + "xBPFO"});
    m.push_back({h * 624.801, std::to_string(h) + "xBPFI"});
  }
  const MarkerLabelLayout l = marker_label_layout(m, 0, 2400, 1100, 600);
  const std::vector<int> rows = marker_label_rows(m, 0, 2400, 0.85 * 1100);
  ASSERT_EQ(l.label_bottom.size(), m.size());
  const double label_px = 6 * kMarkerCharPx;  // "3xBPFO"
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_GT(l.label_bottom[i], l.graph_top) << m[i].label;
    EXPECT_LE(l.label_bottom[i] + label_px / 600, 1 - kTitlePx / 600 + 1e-12) << m[i].label;
    for (std::size_t j = 0; j < m.size(); ++j)
      if (rows[j] == rows[i] + 1) {
        EXPECT_GE(l.label_bottom[j] - l.label_bottom[i], label_px / 600) << m[i].label;
      }
  }
}

// A healthy R's ticks (1.383770 to 1.383795 ohm) need more than %g's 6 digits; a plain range
// none.
TEST(PlotFigures, TickFormatTellsCloseTicksApart)
{
  const std::string f = y_tick_format(1.383770, 1.383795);
  ASSERT_FALSE(f.empty());
  std::set<std::string> printed;
  for (int k = 0; k <= 10; ++k) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f.c_str(), 1.383770 + k * 2.5e-6);
    printed.insert(buf);
  }
  EXPECT_EQ(printed.size(), 11u) << f;
  EXPECT_EQ(y_tick_format(0, 1), "");
  EXPECT_EQ(y_tick_format(-0.004, 0.004), "");
  EXPECT_EQ(y_tick_format(1, 1), "");
}

}  // namespace ohmdem::post
