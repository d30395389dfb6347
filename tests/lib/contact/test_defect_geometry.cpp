// SPDX-License-Identifier: GPL-2.0-or-later
// Unit tests of the defect (pit) geometry kernel, src_fix/lib/contact/defect_geometry.*.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/defect_geometry.h"
#include "test_constants.h"

using ohmdem::test::kPi;

using ohmdem::Pit;

TEST(DefectGeometry, WrapAngle)
{
  EXPECT_DOUBLE_EQ(ohmdem::wrap_angle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(ohmdem::wrap_angle(kPi), kPi);
  EXPECT_DOUBLE_EQ(ohmdem::wrap_angle(-kPi), kPi);
  EXPECT_NEAR(ohmdem::wrap_angle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(ohmdem::wrap_angle(-7 * kPi / 2), kPi / 2, 1e-14);
  EXPECT_NEAR(ohmdem::wrap_angle(1e3), std::remainder(1e3, 2 * kPi), 1e-12);
}

TEST(DefectGeometry, NoRecessOutsideAndContinuousAtTheEdges)
{
  const Pit pit{4.2e-4, 5e-6, 6.3e-3};  // a 1 degree inner-race pit of the 6208, 5 um deep
  EXPECT_EQ(ohmdem::pit_recess(pit, 2.1e-4), 0.0);
  EXPECT_EQ(ohmdem::pit_recess(pit, -3e-4), 0.0);
  EXPECT_FALSE(ohmdem::in_pit(pit, 2.1e-4));
  EXPECT_TRUE(ohmdem::in_pit(pit, 2.09e-4));
  EXPECT_LT(ohmdem::pit_recess(pit, 2.1e-4 - 1e-9), 1e-13);  // continuous: re-entry is smooth
}

TEST(DefectGeometry, SphereOnTheEdgesOfANarrowPit)
{
  // Narrow pit: the ball rests on both edges before reaching the floor. At the centre it sinks
  // by r - sqrt(r^2 - (w/2)^2) (the sagitta of a chord w of a circle of radius r).
  const double r = 6.3e-3, w = 4.2e-4;
  const Pit pit{w, 1e-3, r};
  const double sagitta = r - std::sqrt(r * r - w * w / 4);  // 3.5 um
  EXPECT_NEAR(ohmdem::pit_max_recess(pit), sagitta, 1e-18);
  EXPECT_NEAR(sagitta, 3.5e-6, 0.01e-6);
  // A quarter of the way in: distance w/4 to the nearer edge.
  EXPECT_NEAR(ohmdem::pit_recess(pit, w / 4), r - std::sqrt(r * r - w * w / 16), 1e-18);
  EXPECT_DOUBLE_EQ(ohmdem::pit_recess(pit, -w / 4), ohmdem::pit_recess(pit, w / 4));
}

TEST(DefectGeometry, FloorOfAWidePit)
{
  const Pit pit{5e-3, 5e-6, 6.3e-3};  // 5 mm wide, 5 um deep: the floor is reached
  EXPECT_DOUBLE_EQ(ohmdem::pit_max_recess(pit), 5e-6);
  EXPECT_DOUBLE_EQ(ohmdem::pit_recess(pit, 1e-3), 5e-6);
  // Wider than the ball itself (defects larger than the ball spacing): still the floor.
  const Pit huge{0.05, 5e-6, 6.3e-3};
  EXPECT_DOUBLE_EQ(ohmdem::pit_recess(huge, 0.02), 5e-6);
  EXPECT_TRUE(std::isfinite(ohmdem::pit_recess(huge, 0.0)));
}
