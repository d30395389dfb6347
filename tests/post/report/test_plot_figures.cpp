// SPDX-License-Identifier: GPL-2.0-or-later
// The figures of plot, made from what the library computed: indicators sorted by the swept
// parameter with the rows left out told, their errors in settings; the spectrogram's fault lines
// only with the shaft speed.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "io/read_table.h"
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
}  // namespace ohmdem::post
