// SPDX-License-Identifier: GPL-2.0-or-later
// The 3D cage pocket (src_fix/lib/contact/cage_contact_3d.h): in the bearing plane it is the
// planar pocket (cage_contact.h) bit for bit in force and torque; a ball off the pocket's axis
// axially, or both ways, is pushed back along its offset by Hertz sphere-on-flat of the
// overlap beyond the clearance, and the cage feels the opposite axially.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/cage_contact.h"
#include "contact/cage_contact_3d.h"
#include "johnson_hertz.h"
#include "test_constants.h"

namespace {

constexpr double kRb = 6.3e-3, kClear = 1e-4, kEstar = 3e9, kPitch = 0.0303;
constexpr double kMass = 8e-3;

}  // namespace

TEST(CageContact3d, InThePlaneItIsThePlanarPocket)
{
  const ohmdem::CageContactModel m(kRb, kClear, kEstar, 0.5);
  const ohmdem::Vec2 dir{std::cos(0.4), std::sin(0.4)};
  const ohmdem::Vec2 t{-dir.y, dir.x};
  for (double off : {1.2e-4, -1.5e-4, 5e-5}) {
    ohmdem::CageContactState s2;
    s2.ball_x = {kPitch * dir.x + off * t.x, kPitch * dir.y + off * t.y};
    s2.ball_v = {0.1, 0.2};
    s2.ball_mass = kMass;
    s2.pocket_dir = dir;
    s2.cage_omega = 200;
    ohmdem::CageContactState3d s3;
    s3.ball_x = {s2.ball_x.x, s2.ball_x.y, 0.0};
    s3.ball_v = {0.1, 0.2, 0.0};
    s3.ball_mass = kMass;
    s3.pocket_dir = dir;
    s3.cage_omega = 200;
    const auto r2 = ohmdem::cage_contact(m, s2);
    const auto r3 = ohmdem::cage_contact_3d(m, s3);
    EXPECT_EQ(r3.touching, r2.touching);
    EXPECT_NEAR(r3.fn, r2.fn, 1e-12 * (1 + r2.fn));
    EXPECT_NEAR(r3.force_on_ball.x, r2.force_on_ball.x, 1e-12 * (1 + r2.fn));
    EXPECT_NEAR(r3.force_on_ball.y, r2.force_on_ball.y, 1e-12 * (1 + r2.fn));
    EXPECT_EQ(r3.force_on_ball.z, 0.0);
    EXPECT_NEAR(r3.torque_on_cage, r2.torque_on_cage, 1e-12 * (1 + std::fabs(r2.torque_on_cage)));
  }
}

TEST(CageContact3d, AnAxialOffsetPushesTheBallBackAndTheCageAlong)
{
  const ohmdem::CageContactModel m(kRb, kClear, kEstar, 1.0);
  const double ot = 6e-5, oz = 1.1e-4, d = std::hypot(ot, oz);
  ohmdem::CageContactState3d s;
  s.ball_x = {kPitch, ot, oz + 2e-5};
  s.centre = {0.0, 0.0, 2e-5};
  s.ball_mass = kMass;
  const auto r = ohmdem::cage_contact_3d(m, s);
  ASSERT_TRUE(r.touching);
  EXPECT_NEAR(r.delta, d - kClear, 1e-18);
  // Sphere on flat: 1/rb in both planes (Johnson, the reference of johnson_hertz.h).
  const double K = ohmdem::test::johnson_stiffness(1 / kRb, 1 / kRb * (1 + 1e-9), kEstar);
  EXPECT_NEAR(r.fn / (K * std::pow(d - kClear, 1.5)), 1.0, 1e-6);
  EXPECT_NEAR(r.force_on_ball.y, -r.fn * ot / d, 1e-12 * r.fn);
  EXPECT_NEAR(r.force_on_ball.z, -r.fn * oz / d, 1e-12 * r.fn);
  EXPECT_NEAR(r.axial_on_cage, r.fn * oz / d, 1e-12 * r.fn);
  s.ball_x.z = 2e-5 + 0.9 * kClear;  // within the play
  s.ball_x.y = 0.0;
  EXPECT_FALSE(ohmdem::cage_contact_3d(m, s).touching);
}
