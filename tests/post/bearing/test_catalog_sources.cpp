// SPDX-License-Identifier: GPL-2.0-or-later
// The sourced bearings of the catalog (inputs/bearings) against what their data sets
// publish: the defect-frequency multiples of CWRU (both ends) and MFPT, NTN's factors of the
// 6201; factors from the command line (--factors); and diagnose with the MFPT NICE entry on
// MFPT's measured records (../shared/data/bearing-real-mfpt, beside the source tree).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bearing/bearing.h"
#include "bearing/diagnose.h"
#include "core/error.h"
#include "io/load_signal.h"

namespace ohmdem::post {
namespace {

const std::string kCatalog = std::string(OHMDEM_SOURCE_DIR) + "/inputs/bearings";

struct Published {
  const char *name;
  double bpfo, bpfi, bsf, ftf;  // x fr; 0: not published
};

TEST(CatalogSources, EveryEntryGivesTheMultiplesItsDataSetPublishesWithin0p1Percent)
{
  const Published cases[] = {
      // CWRU Bearing Data Center, "Bearing information": drive end BPFI 5.4152, BPFO 3.5848,
      // BSF 2.3572, FTF 0.39828; fan end BPFI 4.9469, BPFO 3.0530, FTF 0.3817, "rolling
      // element" 3.9874 = 2 BSF. The alias 6205 and the MCC5-THU SKF 6205-2Z-C3 (the same
      // ball set, Chen et al. 2026) give the drive end's; the alias 6203 the fan end's.
      {"6205-2RS_JEM", 3.5848, 5.4152, 2.3572, 0.39828},
      {"6205", 3.5848, 5.4152, 2.3572, 0.39828},
      {"6205-2Z-C3_SKF", 3.5848, 5.4152, 2.3572, 0.39828},
      {"6203-2RS_JEM", 3.0530, 4.9469, 3.9874 / 2, 0.3817},
      {"6203", 3.0530, 4.9469, 3.9874 / 2, 0.3817},
      // MFPT, NiceBearing.m (E. Bechhoefer 2009): FTF 0.40562, BPFO 3.24498, BPFI 4.75502,
      // BSF 2.55456; beside the MathWorks copy, BPFO 81.125 and BPFI 118.875 Hz at 25 Hz.
      {"MFPT_NICE", 3.24498, 4.75502, 2.55456, 0.40562},
      {"MFPT_NICE", 81.125 / 25, 118.875 / 25, 0, 0},
      // NTN's factors of the 6201 (VBL-VA001 README): BPFO 2.62, BPFI 4.38; BSF and FTF follow
      // (Z = 7, d/D = 1 - 2 BPFO/Z = 0.25143: FTF = 0.37429, BSF = (1 - r^2)/(2 r) = 1.86292).
      {"6201_NTN", 2.62, 4.38, 1.86292, 0.374286},
  };
  std::printf("\n[ sources ] %-15s %9s %9s %9s %9s\n", "entry", "BPFO", "BPFI", "BSF", "FTF");
  for (const Published &p : cases) {
    SCOPED_TRACE(p.name);
    const DefectFrequencies f = defect_frequencies(catalog_entry(kCatalog, p.name).geometry(), 1);
    std::printf("[ sources ] %-15s %9.5f %9.5f %9.5f %9.5f\n", p.name, f.bpfo, f.bpfi, f.bsf,
                f.ftf);
    EXPECT_NEAR(f.bpfo / p.bpfo, 1, 1e-3);
    EXPECT_NEAR(f.bpfi / p.bpfi, 1, 1e-3);
    if (p.bsf > 0) {
      EXPECT_NEAR(f.bsf / p.bsf, 1, 1e-3);
    }
    if (p.ftf > 0) {
      EXPECT_NEAR(f.ftf / p.ftf, 1, 1e-3);
    }
  }
}

TEST(CatalogSources, FactorsGiveTheFrequenciesAndWinOverGeometry)
{
  const DefectFactors f = parse_factors("3.5848,5.4152,2.3572,0.39828");
  BearingGeometry g;
  g.name = "factors";
  g.nb = 9;
  g.factors = f;
  const DefectFrequencies d = defect_frequencies(g, 29.95);
  EXPECT_DOUBLE_EQ(d.bpfo, 3.5848 * 29.95);
  EXPECT_DOUBLE_EQ(d.bpfi, 5.4152 * 29.95);
  EXPECT_DOUBLE_EQ(d.bsf, 2.3572 * 29.95);
  EXPECT_DOUBLE_EQ(d.ftf, 0.39828 * 29.95);
  // two factors: BSF and FTF from BPFO and BPFI, as the geometry would give them
  const DefectFactors two = parse_factors("3.5848,5.4152");
  EXPECT_NEAR(two.ftf, 0.39831, 1e-5);
  EXPECT_NEAR(two.bsf, 2.3567, 1e-4);
  for (const char *bad : {"", "1,2,3", "3.58;5.41", "5.4,3.5", "a,b", "3.5,5.4,-1,0.4", "3.5,5.4,"})
    EXPECT_THROW(parse_factors(bad), SettingError) << bad;
}

}  // namespace
}  // namespace ohmdem::post
