// SPDX-License-Identifier: GPL-2.0-or-later
// A ball's orientation and the pit it carries in the 3D bearing (src_fix/lib/contact/
// ball_pit_3d.h): each turn is the exact rotation (Rodrigues' matrix, vec3.h), turns compose in
// the lab frame in the order they happen, and a contact's direction follows the torus' sign of
// the contact angle (torus_race.h).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/ball_pit_3d.h"
#include "contact/vec3.h"

namespace {

using ohmdem::Vec3;

void expect_near(Vec3 a, Vec3 b, double tol)
{
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace

TEST(BallPit3d, TurningAboutZIsTheSpinAngle)
{
  ohmdem::BallOrientation q;
  const double w = 1200.0, dt = 1e-6;
  for (int k = 0; k < 5000; ++k) q.turn({0.0, 0.0, w}, dt);
  const double angle = w * dt * 5000;  // 6 rad: past a turn
  expect_near(q.apply({1.0, 0.0, 0.0}), {std::cos(angle), std::sin(angle), 0.0}, 1e-12);
  expect_near(q.apply({0.0, 0.0, 1.0}), {0.0, 0.0, 1.0}, 1e-12);
}

TEST(BallPit3d, ATurnIsRodriguesRotation)
{
  const Vec3 omega{300.0, -700.0, 450.0};
  const double dt = 2e-3;  // a large angle: 1.8 rad
  ohmdem::BallOrientation q;
  q.turn(omega, dt);
  const ohmdem::Rot3 R = ohmdem::rotation_vector(dt * omega);
  for (Vec3 v : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0.3, -0.2, 0.9}})
    expect_near(q.apply(v), R.apply(v), 1e-14);
}

TEST(BallPit3d, TurnsComposeInTheLabFrameInTheirOrder)
{
  const Vec3 w1{0.0, 0.0, 1.0}, w2{1.0, 0.0, 0.0};
  ohmdem::BallOrientation q;
  q.turn(w1, 0.5 * M_PI);  // x -> y
  q.turn(w2, 0.5 * M_PI);  // then about lab x: y -> z
  expect_near(q.apply({1.0, 0.0, 0.0}), {0.0, 0.0, 1.0}, 1e-15);
  q.turn({0.0, 0.0, 0.0}, 1.0);  // no rotation: unchanged
  expect_near(q.apply({1.0, 0.0, 0.0}), {0.0, 0.0, 1.0}, 1e-15);
}

TEST(BallPit3d, ContactDirectionsFollowTheTorusSign)
{
  // A ball on +x pressed by an inner ring pushed along +z: alpha > 0 on both races; the outer
  // contact lies outward and up, the inner one toward the axis and down, on one line.
  const Vec3 radial{1.0, 0.0, 0.0};
  const double alpha = 0.25;
  const Vec3 out = ohmdem::contact_direction(radial, alpha, false);
  const Vec3 in = ohmdem::contact_direction(radial, alpha, true);
  expect_near(out, {std::cos(alpha), 0.0, std::sin(alpha)}, 1e-16);
  expect_near(in, -1.0 * out, 1e-16);
  EXPECT_NEAR(ohmdem::angle_between(out, in), M_PI, 1e-12);
  EXPECT_NEAR(ohmdem::angle_between(out, ohmdem::ball_pit_centre(0.0, alpha)), 0.0, 1e-12);
  EXPECT_NEAR(ohmdem::angle_between(ohmdem::ball_pit_centre(0.3, 0.0), {0.0, 0.0, 1.0}), 0.5 * M_PI,
              1e-15);
}
