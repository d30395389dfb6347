// SPDX-License-Identifier: GPL-2.0-or-later
// The catalog's MFPT NICE entry on MFPT's measured records beside the repository (skipped when
// absent): diagnose names the family of each fault record.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <string>

#include "bearing/bearing.h"
#include "bearing/diagnose.h"
#include "io/load_signal.h"

namespace ohmdem::post {
namespace {

const std::string kCatalog = std::string(OHMDEM_SOURCE_DIR) + "/inputs/bearings";

bool present(const std::string &path)
{
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

// MFPT's 14 fault records (7 inner, 7 outer, 25 Hz as recorded, 48 828 Hz) with the NICE entry:
// diagnose names the family of each record's file.
TEST(CatalogSources, DiagnoseWithTheNiceEntryFindsTheFamilyOfEachMfptRecord)
{
  const std::string dir = std::string(OHMDEM_SOURCE_DIR) + "/../shared/data/bearing-real-mfpt";
  if (!present(dir + "/README.md")) GTEST_SKIP() << dir << " not found";
  const BearingGeometry nice = catalog_entry(kCatalog, "MFPT_NICE").geometry();
  const char *loads[2][7] = {{"1_0", "2_50", "3_100", "4_150", "5_200", "6_250", "7_300"},
                             {"1_25", "2_50", "3_100", "4_150", "5_200", "6_250", "7_300"}};
  int right = 0;
  for (int k = 0; k < 2; ++k)
    for (const char *load : loads[k]) {
      const std::string kind = k == 0 ? "inner" : "outer";
      InputOptions io;
      io.files = {dir + "/records/mfpt_" + kind + "_vload_" + load + "lbs.mat"};
      io.column = "accel_g";
      io.rate = 48828;
      DiagnoseOptions o;
      o.geometry = nice;
      o.fr = 25;  // as recorded (the README: the shaft ran 0.5-1.3 % slower)
      o.estimate_size = false;
      const Diagnosis d = diagnose(load_signal(io, RunMetadata{}), o);
      std::printf("[ MFPT NICE ] %-6s %-7s lbs: %-6s at %.2f Hz\n", kind.c_str(), load,
                  d.defect.c_str(), d.frequency_hz);
      EXPECT_EQ(d.defect, kind) << io.files[0];
      right += d.defect == kind;
    }
  EXPECT_EQ(right, 14);
}

}  // namespace
}  // namespace ohmdem::post
