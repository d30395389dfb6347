// SPDX-License-Identifier: GPL-2.0-or-later
// run.json as our decks write it (io/run_metadata.h): a model 3d run's "load": "shaft" reads as
// the load zone its shaft load makes (radial with Fr > 0, else force: an axial load loads every
// ball alike); the planar modes are read as written.
#include <gtest/gtest.h>

#include <string>

#include "io/run_metadata.h"
#include "test_util.h"

using ohmdem::post::read_run_metadata;
using ohmdem::post::test::write_temp;

TEST(RunMetadata, AShaftLoadReadsAsTheLoadZoneItMakes)
{
  const auto radial = write_temp("run3d_radial.json",
                                 R"({"load": "shaft", "model": "3d", "Fr": 1000, "Fa": 300})");
  const auto axial =
      write_temp("run3d_axial.json", R"({"load": "shaft", "model": "3d", "Fr": 0, "Fa": 500})");
  EXPECT_EQ(read_run_metadata(radial).load.value_or(""), "radial");
  EXPECT_EQ(read_run_metadata(axial).load.value_or(""), "force");
}

TEST(RunMetadata, APlanarLoadIsReadAsWritten)
{
  for (const std::string mode : {"force", "fixed", "radial"}) {
    const auto path = write_temp("run2d_" + mode + ".json", R"({"load": ")" + mode + R"("})");
    EXPECT_EQ(read_run_metadata(path).load.value_or(""), mode);
  }
}
