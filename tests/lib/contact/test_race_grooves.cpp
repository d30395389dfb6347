// SPDX-License-Identifier: GPL-2.0-or-later
// Where the 3D bearing's grooves lie (src_fix/lib/contact/race_grooves.*): a clearance gives
// Harris' free contact angle cos(alpha0) = 1 - Pd/(2A) when the inner ring takes up the play
// axially; a nominal angle alpha0 puts a ball on the pitch circle in contact with both races at
// exactly alpha0; impossible inputs are refused with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "contact/race_grooves.h"
#include "contact/torus_race.h"
#include "test_constants.h"

namespace {

using ohmdem::RaceSide;
using ohmdem::TorusGroove;
using ohmdem::test::kPi;

constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
constexpr double kA = kRcInn + kRcExt - 2 * kRb;

TorusGroove torus(RaceSide side, const ohmdem::GrooveCircle &c)
{
  TorusGroove g;
  g.side = side;
  g.ball_radius = kRb;
  g.groove_radius = side == RaceSide::Inner ? kRcInn : kRcExt;
  g.centre_radius = c.centre_radius;
  g.centre_z = c.centre_z;
  return g;
}

}  // namespace

TEST(RaceGrooves, ClearanceGivesHarrisFreeContactAngle)
{
  for (double c : {0.0, 5e-6, 20e-6, 50e-6}) {
    const auto gi = ohmdem::groove_circle(RaceSide::Inner, kRinn, kRcInn, kRb, c, 0.0);
    const auto go = ohmdem::groove_circle(RaceSide::Outer, kRext, kRcExt, kRb, c, 0.0);
    // Radially the curvature centres are A - c/2 apart; the play is c/4 on each side.
    EXPECT_NEAR(gi.centre_radius - go.centre_radius, kA - c / 2, 1e-15);
    EXPECT_NEAR(gi.centre_radius - (kRinn + kRcInn), -c / 4, 1e-16);
    // Push the inner ring axially until the centres are A apart: the ball halfway between
    // them touches both races at Harris' alpha0.
    const double shift = std::sqrt(kA * kA - (kA - c / 2) * (kA - c / 2));
    TorusGroove ti = torus(RaceSide::Inner, gi), to = torus(RaceSide::Outer, go);
    ti.centre_z += shift;
    // The ball centre on the line from P_o, Rco - r from it.
    const double cos_a = (kA - c / 2) / kA, sin_a = shift / kA, d = kRcExt - kRb;
    const ohmdem::Vec3 x{go.centre_radius + d * cos_a, 0.0, d * sin_a};
    const auto ri = ohmdem::torus_geometry(ti, x), ro = ohmdem::torus_geometry(to, x);
    const double harris = std::acos(1 - c / (2 * kA));
    EXPECT_NEAR(std::atan2(ri.sin_alpha, ri.cos_alpha), harris, 1e-9) << c;
    EXPECT_NEAR(std::atan2(ro.sin_alpha, ro.cos_alpha), harris, 1e-9) << c;
    EXPECT_NEAR(ri.delta, 0.0, 1e-15);
    EXPECT_NEAR(ro.delta, 0.0, 1e-15);
    EXPECT_NEAR(ohmdem::free_contact_angle(c, kA), harris, 1e-15);
  }
}

TEST(RaceGrooves, ANominalAngleTouchesBothRacesThere)
{
  for (double deg : {15.0, 25.0, 40.0}) {
    const double a0 = deg * kPi / 180;
    const auto gi = ohmdem::groove_circle(RaceSide::Inner, kRinn, kRcInn, kRb, 0.0, a0);
    const auto go = ohmdem::groove_circle(RaceSide::Outer, kRext, kRcExt, kRb, 0.0, a0);
    const ohmdem::Vec3 x{kRinn + kRb, 0.0, 0.0};  // on the pitch circle, in the plane
    const auto ri = ohmdem::torus_geometry(torus(RaceSide::Inner, gi), x);
    const auto ro = ohmdem::torus_geometry(torus(RaceSide::Outer, go), x);
    EXPECT_NEAR(ri.delta, 0.0, 1e-16);
    EXPECT_NEAR(ro.delta, 0.0, 1e-16);
    EXPECT_NEAR(std::atan2(ri.sin_alpha, ri.cos_alpha), a0, 1e-12);
    EXPECT_NEAR(std::atan2(ro.sin_alpha, ro.cos_alpha), a0, 1e-12);
    // The curvature centres are A apart along alpha0.
    EXPECT_NEAR(std::hypot(gi.centre_radius - go.centre_radius, gi.centre_z - go.centre_z), kA,
                1e-15);
  }
}

TEST(RaceGrooves, ImpossibleInputsAreRefused)
{
  EXPECT_THROW(ohmdem::groove_circle(RaceSide::Inner, kRinn, kRcInn, kRb, -1e-6, 0.0),
               std::invalid_argument);
  EXPECT_THROW(ohmdem::groove_circle(RaceSide::Inner, kRinn, kRcInn, kRb, 1e-5, 0.3),
               std::invalid_argument);
  EXPECT_THROW(ohmdem::groove_circle(RaceSide::Inner, kRinn, kRcInn, kRb, 0.0, kPi / 2),
               std::invalid_argument);
  EXPECT_THROW(ohmdem::groove_circle(RaceSide::Inner, kRinn, kRb, kRb, 0.0, 0.0),
               std::invalid_argument);
  try {
    ohmdem::free_contact_angle(2.5 * kA, kA);
    FAIL() << "a clearance past 2A was accepted";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("pass between the grooves"), std::string::npos);
  }
}
