// SPDX-License-Identifier: GPL-2.0-or-later
// The table of a bearing's kinematic lines (post/bearing/defect_lines.h): peak labels and the
// kurtogram's band width.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bearing/defect_lines.h"
#include "bearing/fault_bands.h"
#include "core/error.h"
#include "dsp/spectrogram.h"
#include "dsp/spectrum.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

// Round numbers, so each line is easy to place by hand.
DefectFrequencies lines()
{
  DefectFrequencies k;
  k.fr = 10;
  k.ftf = 4;
  k.bpfo = 36;
  k.bpfi = 54;
  k.bsf = 23;
  return k;
}

TEST(DefectLines, TableOrderKeysAndValues)
{
  std::vector<std::string> keys, fault;
  std::vector<double> f;
  for (const DefectLine &l : defect_lines()) {
    keys.push_back(l.key);
    f.push_back(l.of(lines()));
    if (l.fault_line) fault.push_back(l.name);
  }
  EXPECT_EQ(keys, (std::vector<std::string>{"fr", "ftf", "bpfo", "bpfi", "bsf", "two_bsf"}));
  EXPECT_EQ(f, (std::vector<double>{10, 4, 36, 54, 23, 46}));
  EXPECT_EQ(fault, (std::vector<std::string>{"FTF", "BPFO", "BPFI", "2BSF"}));
  std::set<std::string> families;
  for (const DefectLine &l : defect_lines()) families.insert(l.defect);
  EXPECT_EQ(families, (std::set<std::string>{"", "inner", "outer", "ball", "cage"}));
}

TEST(DefectLines, LabelsTheNearestHarmonicWithinTolerance)
{
  const DefectFrequencies k = lines();
  EXPECT_EQ(label_frequency(2 * 36 * 1.01, k, 5, 0.02), "2xBPFO");
  EXPECT_EQ(label_frequency(54, k, 5, 0.02), "1xBPFI");
  EXPECT_EQ(label_frequency(2 * 36 * 1.03, k, 5, 0.02), "");  // outside 2 %
  EXPECT_EQ(label_frequency(6 * 36, k, 5, 0.02), "4xBPFI");   // 216 = 4 x 54; 6 x BPFO > N
  EXPECT_EQ(label_frequency(6 * 36, k, 6, 0.02), "4xBPFI");   // tie with 6xBPFO: the later line
  EXPECT_EQ(label_frequency(2, k, 5, 0.02), "");
  EXPECT_EQ(harmonic_label(1, defect_lines()[2], false), "BPFO");
  EXPECT_EQ(harmonic_label(2, defect_lines()[5], false), "2x2BSF");
}

TEST(DefectLines, KurtogramBandCarriesTheHarmonicsOfTheFastestLine)
{
  const DefectFrequencies k = lines();
  EXPECT_DOUBLE_EQ(highest_defect_frequency(k), 54);  // BPFI > 2 BSF = 46 > BPFO
  EXPECT_DOUBLE_EQ(defect_band_width(k, 5, 10000), 1.1 * 5 * 54);
  EXPECT_DOUBLE_EQ(defect_band_width(k, 5, 1000), 250);  // at most a quarter of the rate
  DefectFrequencies ball = k;
  ball.bsf = 40;  // 2 BSF = 80 is now the fastest
  EXPECT_DOUBLE_EQ(highest_defect_frequency(ball), 80);
}

}  // namespace
}  // namespace ohmdem::post
