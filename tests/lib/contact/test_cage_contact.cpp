// SPDX-License-Identifier: GPL-2.0-or-later
// The ball–pocket contact kernel of the cage (src_fix/lib/contact/cage_contact.*) against
// references written here: a pocket is a slot whose flat walls lie at +-(ball radius +
// clearance) from the radial line through its centre (doc/fix_bearing_cage.md); a ball past
// the play presses a wall as a sphere on a flat, Hertz Q = (4/3) E* sqrt(rb) delta^1.5
// (doc/methods/hertz_contact.md, the sphere case), along the wall's normal, with the restitution
// damping of LIGGGHTS' Hertz model (contact/damping.h) and no friction.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/cage_contact.h"
#include "test_constants.h"

namespace {

using ohmdem::CageContactModel;
using ohmdem::CageContactResult;
using ohmdem::CageContactState;
using ohmdem::Vec2;
using ohmdem::test::kPi;

// SKF 6208 with the deck's cage (inputs/bearing_6208/in.bearing): ball radius, pitch radius
// of the pockets, play per side (m); a steel ball (E = 200 GPa, nu = 0.3) on a PA66 cage
// (E = 3 GPa, nu = 0.4): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
constexpr double kRb = 6.3e-3, kPitch = 0.0303, kClearance = 1e-4;
constexpr double kEstar = 1 / ((1 - 0.3 * 0.3) / 200e9 + (1 - 0.4 * 0.4) / 3e9);
constexpr double kMass = 7850 * 4.0 / 3.0 * kPi * kRb * kRb * kRb;  // steel ball (kg)

// Sphere on a flat (Johnson's sphere case with R* = rb): Q = (4/3) E* sqrt(rb) delta^1.5.
double sphere_on_flat_force(double delta, double Estar = kEstar)
{
  return 4.0 / 3.0 * Estar * std::sqrt(kRb) * delta * std::sqrt(delta);
}

// Pocket 3 of 13 on a cage whose axis is off the origin.
const Vec2 kAxis{2e-4, -1e-4};
const double kPocketAngle = 2 * kPi * 3 / 13;

Vec2 pocket_dir()
{
  return {std::cos(kPocketAngle), std::sin(kPocketAngle)};
}
Vec2 pocket_tangent()  // z x pocket_dir
{
  return {-std::sin(kPocketAngle), std::cos(kPocketAngle)};
}

// The ball on the pitch circle, `offset` (m) from the pocket's centre line along the tangent.
CageContactState state(double offset)
{
  const Vec2 d = pocket_dir(), t = pocket_tangent();
  CageContactState s;
  s.ball_x = {kAxis.x + kPitch * d.x + offset * t.x, kAxis.y + kPitch * d.y + offset * t.y};
  s.ball_mass = kMass;
  s.centre = kAxis;
  s.pocket_dir = d;
  return s;
}

double rel(double x, double ref)
{
  return std::fabs(x / ref - 1);
}

}  // namespace

TEST(CageContact, NoForceInsideThePocketPlay)
{
  const CageContactModel m(kRb, kClearance, kEstar, 0.5);
  for (double offset :
       {0.0, 0.3 * kClearance, -0.7 * kClearance, 0.999 * kClearance, -0.999 * kClearance}) {
    const CageContactResult r = ohmdem::cage_contact(m, state(offset));
    EXPECT_FALSE(r.touching) << offset;
    EXPECT_EQ(r.fn, 0.0);
    EXPECT_EQ(r.force_on_ball.x, 0.0);
    EXPECT_EQ(r.force_on_ball.y, 0.0);
    EXPECT_EQ(r.torque_on_cage, 0.0);
    EXPECT_NEAR(r.offset, offset, 3e-17);  // where the ball sits in its pocket
    EXPECT_NEAR(r.delta, std::fabs(offset) - kClearance, 3e-17);
  }
  // A pocket without play and a ball exactly on its centre line: touching neither wall.
  const CageContactModel tight(kRb, 0.0, kEstar, 0.5);
  CageContactState s;
  s.ball_x = {kPitch, 0.0};
  s.pocket_dir = {1.0, 0.0};
  const CageContactResult r = ohmdem::cage_contact(tight, s);
  EXPECT_FALSE(r.touching);
  EXPECT_EQ(r.delta, 0.0);
  EXPECT_EQ(r.fn, 0.0);
}

TEST(CageContact, HertzSphereOnAFlatWall)
{
  const CageContactModel m(kRb, kClearance, kEstar, 1.0);  // restitution 1: no damping
  for (double delta : {1e-9, 1e-7, 1e-6, 1e-5}) {
    for (double side : {1.0, -1.0}) {
      const CageContactResult r = ohmdem::cage_contact(m, state(side * (kClearance + delta)));
      ASSERT_TRUE(r.touching);
      EXPECT_NEAR(r.delta, delta, 3e-17);
      EXPECT_LT(rel(r.fn, sphere_on_flat_force(r.delta)), 1e-13) << delta;
    }
  }
  // Without play the first nanometre off the centre line is already an approach.
  const CageContactModel tight(kRb, 0.0, kEstar, 1.0);
  const CageContactResult r = ohmdem::cage_contact(tight, state(-1e-9));
  ASSERT_TRUE(r.touching);
  EXPECT_LT(rel(r.fn, sphere_on_flat_force(r.delta)), 1e-13);
  EXPECT_NEAR(r.delta, 1e-9, 3e-17);
}

TEST(CageContact, TheWallPushesTheBallBackAcrossThePocket)
{
  const CageContactModel m(kRb, kClearance, kEstar, 1.0);
  const Vec2 d = pocket_dir(), t = pocket_tangent();
  for (double side : {1.0, -1.0}) {
    const CageContactResult r = ohmdem::cage_contact(m, state(side * (kClearance + 2e-6)));
    ASSERT_TRUE(r.touching);
    // Along the wall's normal, back towards the centre line; nothing radial (the races, not
    // the cage, hold the balls radially).
    EXPECT_NEAR(r.force_on_ball.x, -side * r.fn * t.x, 1e-12 * r.fn);
    EXPECT_NEAR(r.force_on_ball.y, -side * r.fn * t.y, 1e-12 * r.fn);
    EXPECT_NEAR(r.force_on_ball.x * d.x + r.force_on_ball.y * d.y, 0.0, 1e-12 * r.fn);
    // The cage gets the opposite force at the contact point, the pitch radius along the
    // pocket: a moment side * fn * pitch about its axis (a ball ahead of its pocket's centre
    // drives the cage forwards).
    EXPECT_LT(rel(r.torque_on_cage, side * r.fn * kPitch), 1e-12);
  }
}

// LIGGGHTS' Hertz damping (contact/damping.h, written out here): gamma = -2 sqrt(5/6) beta
// sqrt(S m), beta = ln e / sqrt(ln^2 e + pi^2), S = dQ/ddelta = 2 E* sqrt(rb delta); the force
// never pulls (no adhesion).
TEST(CageContact, RestitutionDampingOfTheWallsMotionAndNoAdhesion)
{
  const double e = 0.3, delta = 1e-6, omega = -0.5;
  const double beta = std::log(e) / std::sqrt(std::log(e) * std::log(e) + kPi * kPi);
  const CageContactModel m(kRb, kClearance, kEstar, e);
  // A ball at rest ahead of its pocket's centre; the cage turns backwards (omega < 0), so the
  // +t wall closes on the ball at |omega| times the pitch radius of the contact point.
  CageContactState s = state(kClearance + delta);
  s.cage_omega = omega;
  const CageContactResult r = ohmdem::cage_contact(m, s);
  ASSERT_TRUE(r.touching);
  const double rate = -omega * kPitch;
  const double sn = 2 * kEstar * std::sqrt(kRb * r.delta);
  const double gamma = -2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(sn * kMass);
  EXPECT_LT(rel(r.fn, sphere_on_flat_force(r.delta) + gamma * rate), 1e-12);
  EXPECT_GT(r.fn, sphere_on_flat_force(r.delta));
  // The same closing rate from the ball moving into the still wall gives the same force.
  CageContactState moving = state(kClearance + delta);
  const Vec2 t = pocket_tangent();
  moving.ball_v = {rate * t.x, rate * t.y};
  EXPECT_LT(rel(ohmdem::cage_contact(m, moving).fn, r.fn), 1e-12);
  // Radial motion of the ball along the pocket does not change the approach.
  const Vec2 d = pocket_dir();
  moving.ball_v = {rate * t.x + 3 * d.x, rate * t.y + 3 * d.y};
  EXPECT_LT(rel(ohmdem::cage_contact(m, moving).fn, r.fn), 1e-12);
  // The wall running away fast: the damping would pull, the force stops at zero.
  s.cage_omega = 1e4;
  const CageContactResult away = ohmdem::cage_contact(m, s);
  EXPECT_TRUE(away.touching);
  EXPECT_EQ(away.fn, 0.0);
  EXPECT_EQ(away.force_on_ball.x, 0.0);
  EXPECT_EQ(away.torque_on_cage, 0.0);
}

TEST(CageContact, AVeryStiffContactScalesWithTheModulus)
{
  // E* 10^4 times the PA66 cage's: the force scales by 10^4 and stays finite, also a millimetre
  // deep.
  const CageContactModel soft(kRb, kClearance, kEstar, 1.0);
  const CageContactModel stiff(kRb, kClearance, 1e4 * kEstar, 1.0);
  for (double delta : {1e-9, 1e-6, 1e-3}) {
    const CageContactState s = state(-(kClearance + delta));
    const CageContactResult a = ohmdem::cage_contact(soft, s), b = ohmdem::cage_contact(stiff, s);
    ASSERT_TRUE(std::isfinite(b.fn) && std::isfinite(b.torque_on_cage)) << delta;
    EXPECT_LT(rel(b.fn, 1e4 * a.fn), 1e-12) << delta;
    EXPECT_LT(rel(b.fn, sphere_on_flat_force(b.delta, 1e4 * kEstar)), 1e-13) << delta;
  }
}

TEST(CageContact, InvalidModelsThrowClearly)
{
  auto message = [](auto make) -> std::string {
    try {
      make();
    } catch (const std::invalid_argument &e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message([] { CageContactModel(kRb, -1e-6, kEstar, 0.5); }),
            "pocket clearance must be >= 0");
  EXPECT_EQ(message([] { CageContactModel(kRb, kClearance, kEstar, 0.0); }),
            "coefficient of restitution must be in (0, 1]");
  EXPECT_EQ(message([] { CageContactModel(kRb, kClearance, kEstar, 1.5); }),
            "coefficient of restitution must be in (0, 1]");
}
