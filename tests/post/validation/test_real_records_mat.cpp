// SPDX-License-Identifier: GPL-2.0-or-later
// The MAT reader on the measured CWRU records beside the repository (skipped when absent): a
// record's .mat gives the statistics of its .txt, and its RPM scalar.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dsp/stats.h"
#include "io/load_signal.h"
#include "io/read_mat.h"

namespace ohmdem::post {
namespace {

TEST(Mat, CwruMatGivesTheStatisticsOfTheText)
{
  const std::string dir = std::string(OHMDEM_SOURCE_DIR) + "/../shared/data/bearing-real";
  struct stat st {};
  if (::stat((dir + "/sig01.mat").c_str(), &st) != 0) GTEST_SKIP() << dir << " not found";
  for (const char *rec : {"sig01", "sig05"}) {
    InputOptions m;
    m.files = {dir + "/" + rec + ".mat"};
    m.column = "DE_time";
    m.rate = 12000;
    InputOptions t;
    t.files = {dir + "/" + rec + ".txt"};
    t.rate = 12000;
    const Signal sm = load_signal(m, {}), st2 = load_signal(t, {});
    ASSERT_EQ(sm.size(), st2.size()) << rec;
    const Indicators a = indicators(sm.x), b = indicators(st2.x);
    // the text holds the same values printed with 8 significant digits (README of the data)
    for (auto [u, v] : {std::pair{a.rms, b.rms},
                        {a.peak, b.peak},
                        {a.kurtosis, b.kurtosis},
                        {a.skewness, b.skewness},
                        {a.crest, b.crest}})
      EXPECT_NEAR(u, v, 1e-6 * std::fabs(v)) << rec;
    EXPECT_NEAR(a.mean, b.mean, 1e-8) << rec;
    double worst = 0;
    for (std::size_t i = 0; i < sm.size(); ++i)
      worst = std::max(worst, std::fabs(sm.x[i] - st2.x[i]) / std::max(1e-3, std::fabs(sm.x[i])));
    EXPECT_LT(worst, 1e-7) << rec;
  }
  EXPECT_EQ(read_mat_scalar(dir + "/sig05.mat", "RPM"), 1721.0);  // README: 1721 rpm
}

}  // namespace
}  // namespace ohmdem::post
