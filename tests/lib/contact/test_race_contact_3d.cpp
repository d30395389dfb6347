// SPDX-License-Identifier: GPL-2.0-or-later
// The 3D ball-race contact kernel (src_fix/lib/contact/race_contact_3d.*) against closed forms
// and the planar kernel: in the bearing plane it is race_contact (same force, torque, point);
// along a contact line at angle alpha the force is K(alpha) delta^1.5 on that line (Johnson's
// Hertz, johnson_hertz.h); a tilted and displaced ring turns the answer with it; rolling
// without slip and without relative spin needs no friction; Coulomb caps the tangential force
// at mu Q and the spin moment at Harris' 3 mu Q a E(e)/8; the torsional spring is Mindlin's.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/race_contact.h"
#include "contact/race_contact_3d.h"
#include "johnson_hertz.h"
#include "test_constants.h"

namespace {

using ohmdem::BallState3d;
using ohmdem::RaceContactModel3d;
using ohmdem::RaceSide;
using ohmdem::RingMotion3d;
using ohmdem::Rot3;
using ohmdem::TorusGroove;
using ohmdem::Vec3;
using ohmdem::test::kPi;

constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
constexpr double kE = 200e9, kNu = 0.3, kMu = 0.1;
constexpr double kEstar = kE / (2 * (1 - kNu * kNu));
constexpr double kGstar = kE / (4 * (2 - kNu) * (1 + kNu));
constexpr double kGt = kE / (4 * (1 + kNu));
constexpr double kMass = 7850 * 4.0 / 3.0 * kPi * kRb * kRb * kRb;
constexpr double kInertia = 0.4 * kMass * kRb * kRb;

TorusGroove groove(RaceSide side)
{
  const bool inner = side == RaceSide::Inner;
  TorusGroove g;
  g.side = side;
  g.ball_radius = kRb;
  g.groove_radius = inner ? kRcInn : kRcExt;
  g.centre_radius = inner ? kRinn + kRcInn : kRext - kRcExt;
  return g;
}

RaceContactModel3d model(RaceSide side, double restitution = 1.0, double mu = kMu)
{
  return RaceContactModel3d(groove(side), kEstar, kGstar, kGt, restitution, mu);
}

struct History {
  double shear[3] = {0, 0, 0};
  double twist = 0;
  ohmdem::ContactHistory3d view() { return {shear, &twist}; }
};

// A ball on the contact line at angle alpha, azimuth phi, approach delta (ring frame).
Vec3 ball_at(RaceSide side, double phi, double alpha, double delta)
{
  const TorusGroove g = groove(side);
  const double s = side == RaceSide::Inner ? -1.0 : 1.0;
  const double d = g.groove_radius - kRb + delta;
  const double rho = g.centre_radius + s * d * std::cos(alpha);
  return {rho * std::cos(phi), rho * std::sin(phi), g.centre_z + s * d * std::sin(alpha)};
}

BallState3d ball(Vec3 x)
{
  BallState3d b;
  b.x = x;
  b.mass = kMass;
  b.inertia = kInertia;
  return b;
}

}  // namespace

TEST(RaceContact3d, InThePlaneItIsThePlanarKernel)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const bool inner = side == RaceSide::Inner;
    const ohmdem::RaceContactModel planar(side, kRb, inner ? kRinn : kRext, inner ? kRcInn : kRcExt,
                                          kEstar, kGstar, 0.5, kMu);
    const RaceContactModel3d m = model(side, 0.5);
    const double phi = 0.7, delta = 3e-6, dt = 1e-7;
    const Vec3 x = ball_at(side, phi, 0.0, delta);
    ohmdem::RaceContactState s2;
    s2.ball_x = {x.x, x.y};
    s2.ball_v = {0.3, -0.2};
    s2.ball_omega = 150.0;
    s2.ball_mass = kMass;
    s2.race_radius = inner ? kRinn : kRext;
    s2.race_omega = 40.0;
    double shear2 = 0;
    const auto r2 = ohmdem::race_contact(planar, s2, dt, true, shear2);
    BallState3d b = ball(x);
    b.v = {0.3, -0.2, 0.0};
    b.omega = {0.0, 0.0, 150.0};
    RingMotion3d ring;
    ring.omega = {0.0, 0.0, 40.0};
    History h;
    const auto r3 = ohmdem::race_contact_3d(m, ring, b, 0.0, dt, true, h.view());
    ASSERT_TRUE(r2.touching && r3.touching);
    EXPECT_NEAR(r3.delta, r2.delta, 1e-17);  // a few ulp of 30 mm
    EXPECT_NEAR(r3.fn / r2.fn, 1.0, 1e-11);
    EXPECT_NEAR(r3.ft_rolling / r2.ft, 1.0, 1e-9);
    EXPECT_NEAR(r3.force_on_ball.x, r2.force_on_ball.x, 1e-10 * r2.fn);
    EXPECT_NEAR(r3.force_on_ball.y, r2.force_on_ball.y, 1e-10 * r2.fn);
    EXPECT_EQ(r3.force_on_ball.z, 0.0);
    EXPECT_NEAR(r3.torque_on_ball.z, r2.torque_on_ball, 1e-9 * std::fabs(r2.torque_on_ball));
    EXPECT_NEAR(r3.torque_on_ring.z, r2.torque_on_race, 1e-9 * std::fabs(r2.torque_on_race));
    EXPECT_NEAR(r3.point.x, r2.point.x, 1e-17);
    EXPECT_NEAR(r3.point.y, r2.point.y, 1e-17);
    EXPECT_NEAR(h.shear[0] * r2.normal.y - h.shear[1] * r2.normal.x, -shear2,
                1e-11 * std::fabs(shear2));
  }
}

TEST(RaceContact3d, AlongAContactLineTheForceIsHertzAtThatAngle)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const RaceContactModel3d m = model(side);
    for (double alpha_deg : {-20.0, 8.0, 30.0, 45.0}) {
      const double alpha = alpha_deg * kPi / 180, delta = 5e-6;
      History h;
      const auto r = ohmdem::race_contact_3d(
          m, RingMotion3d{}, ball(ball_at(side, 1.1, alpha, delta)), 0.0, 1e-7, true, h.view());
      ASSERT_TRUE(r.touching);
      const auto s = ohmdem::torus_curvatures(groove(side), std::cos(alpha));
      const double K = ohmdem::test::johnson_stiffness(s.A, s.B, kEstar);
      EXPECT_NEAR(r.fn / (K * std::pow(delta, 1.5)), 1.0, 1e-8) << alpha_deg;
      EXPECT_NEAR(r.sin_alpha, std::sin(alpha), 1e-12);
      // On the contact line: the force on the ball is -fn m, m from the circle to the ball.
      const double sgn = side == RaceSide::Inner ? -1.0 : 1.0;
      const Vec3 m_ref{sgn * std::cos(alpha) * std::cos(1.1), sgn * std::cos(alpha) * std::sin(1.1),
                       sgn * std::sin(alpha)};
      EXPECT_NEAR(r.force_on_ball.x, -r.fn * m_ref.x, 1e-9 * r.fn);
      EXPECT_NEAR(r.force_on_ball.y, -r.fn * m_ref.y, 1e-9 * r.fn);
      EXPECT_NEAR(r.force_on_ball.z, -r.fn * m_ref.z, 1e-9 * r.fn);
      EXPECT_NEAR(ohmdem::norm(r.torque_on_ball), 0.0, 1e-12 * r.fn * kRb);
    }
  }
}

TEST(RaceContact3d, ATiltedDisplacedRingTurnsTheAnswerWithIt)
{
  const RaceContactModel3d m = model(RaceSide::Outer);
  const Rot3 tilt = ohmdem::rotation_vector({0.02, -0.035, 0.0});
  const Vec3 c{1e-4, -2e-4, 3e-4};
  const Vec3 local = ball_at(RaceSide::Outer, 0.4, 0.25, 4e-6);
  History h0, h1;
  const auto r0 =
      ohmdem::race_contact_3d(m, RingMotion3d{}, ball(local), 0.0, 0.0, false, h0.view());
  RingMotion3d ring;
  ring.centre = c;
  ring.tilt = tilt;
  ring.tilted = true;
  const auto r1 =
      ohmdem::race_contact_3d(m, ring, ball(c + tilt.apply(local)), 0.0, 0.0, false, h1.view());
  const Vec3 f = tilt.apply(r0.force_on_ball);
  EXPECT_NEAR(r1.fn / r0.fn, 1.0, 1e-9);
  EXPECT_NEAR(r1.force_on_ball.x, f.x, 1e-9 * r0.fn);
  EXPECT_NEAR(r1.force_on_ball.y, f.y, 1e-9 * r0.fn);
  EXPECT_NEAR(r1.force_on_ball.z, f.z, 1e-9 * r0.fn);
  const Vec3 t = tilt.apply(r0.torque_on_ring);
  EXPECT_NEAR(r1.torque_on_ring.x, t.x, 1e-9 * r0.fn * kRext);
  EXPECT_NEAR(r1.torque_on_ring.z, t.z, 1e-9 * r0.fn * kRext);
}

TEST(RaceContact3d, RollingWithoutSlipOrSpinNeedsNoFriction)
{
  // The ball turns about an axis through its centre such that its contact point moves with
  // the ring's material there, and the relative spin about the normal is zero.
  const RaceContactModel3d m = model(RaceSide::Inner);
  const double alpha = 0.3, delta = 3e-6, w_ring = 300.0;
  const Vec3 x = ball_at(RaceSide::Inner, 0.0, alpha, delta);
  History h;
  RingMotion3d ring;
  ring.omega = {0.0, 0.0, w_ring};
  auto probe = ohmdem::race_contact_3d(m, ring, ball(x), 0.0, 0.0, false, h.view());
  const Vec3 p = probe.point, n = probe.normal;
  const Vec3 vr = ohmdem::cross(ring.omega, p);  // the ring's material at p
  // omega_ball = w_n n + n x (vr)/|lever|... solve omega x lever = vr with lever = p - x.
  const Vec3 lever = p - x;
  const double l2 = ohmdem::dot(lever, lever);
  Vec3 w = (1.0 / l2) * ohmdem::cross(lever, vr);
  w = w + (ohmdem::dot(ring.omega, n) - ohmdem::dot(w, n)) * n;  // no relative spin
  BallState3d b = ball(x);
  b.omega = w;
  for (int k = 0; k < 5; ++k) {
    const auto r = ohmdem::race_contact_3d(m, ring, b, 0.0, 1e-7, true, h.view());
    EXPECT_NEAR(ohmdem::norm(r.force_on_ball + r.fn * n), 0.0, 1e-9 * r.fn);
    EXPECT_NEAR(r.spin_moment, 0.0, 1e-12 * r.fn * kRb);
  }
}

TEST(RaceContact3d, CoulombCapsSlidingAndSpin)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const RaceContactModel3d m = model(side);
    const double alpha = 0.35, delta = 6e-6;
    BallState3d b = ball(ball_at(side, 0.2, alpha, delta));
    b.v = {0.0, 0.0, 2.0};  // sliding across the groove
    b.omega = {0.0, 0.0, 0.0};
    History h;
    ohmdem::RaceContactResult3d r;
    for (int k = 0; k < 50; ++k)
      r = ohmdem::race_contact_3d(m, RingMotion3d{}, b, 0.0, 1e-6, true, h.view());
    const Vec3 ft = r.force_on_ball + r.fn * r.normal;
    EXPECT_NEAR(ohmdem::norm(ft) / (kMu * r.fn), 1.0, 1e-9);
    EXPECT_NEAR(ohmdem::dot(ft, r.normal), 0.0, 1e-9 * r.fn);
    // Spinning about the normal: the full-sliding moment of Harris, 3 mu Q a E(e)/8.
    History hs;
    BallState3d bs = ball(b.x);
    bs.omega = 500.0 * r.normal;
    for (int k = 0; k < 200; ++k)
      r = ohmdem::race_contact_3d(m, RingMotion3d{}, bs, 0.0, 1e-5, true, hs.view());
    const auto s = ohmdem::torus_curvatures(groove(side), r.cos_alpha);
    const auto j = ohmdem::test::johnson_hertz(s.A, s.B, kEstar, r.fn);
    EXPECT_NEAR(r.spin_moment / (-3 * kMu * r.fn * j.a * j.E_ecc / 8), 1.0, 1e-8);
  }
}

TEST(RaceContact3d, TheTorsionalSpringIsMindlins)
{
  const RaceContactModel3d m = model(RaceSide::Inner, 1.0, 10.0);  // mu large: no slip
  const double alpha = 0.2, delta = 5e-6, dt = 1e-8, w = 1.0;
  BallState3d b = ball(ball_at(RaceSide::Inner, 0.0, alpha, delta));
  History h;
  auto r = ohmdem::race_contact_3d(m, RingMotion3d{}, b, 0.0, dt, false, h.view());
  b.omega = w * r.normal;
  r = ohmdem::race_contact_3d(m, RingMotion3d{}, b, 0.0, dt, true, h.view());
  EXPECT_NEAR(h.twist, w * dt, 1e-22);
  // M = -k theta - gamma w with restitution 1 (no damping): k = (16/3) G_t (ab)^(3/2).
  const auto s = ohmdem::torus_curvatures(groove(RaceSide::Inner), r.cos_alpha);
  const auto j = ohmdem::test::johnson_hertz(s.A, s.B, kEstar, r.fn);
  EXPECT_NEAR(r.spin_moment / (-16.0 / 3 * kGt * std::pow(j.a * j.b, 1.5) * w * dt), 1.0, 1e-8);
}

TEST(RaceContact3d, APitLowersTheSurfaceAndNoContactResetsTheHistory)
{
  const RaceContactModel3d m = model(RaceSide::Outer);
  BallState3d b = ball(ball_at(RaceSide::Outer, 0.0, 0.1, 2e-6));
  History h;
  h.shear[0] = 1e-7;
  h.twist = 1e-3;
  auto r = ohmdem::race_contact_3d(m, RingMotion3d{}, b, 1e-6, 0.0, false, h.view());
  EXPECT_NEAR(r.delta, 1e-6, 1e-17);
  r = ohmdem::race_contact_3d(m, RingMotion3d{}, b, 3e-6, 0.0, false, h.view());
  EXPECT_FALSE(r.touching);
  EXPECT_EQ(r.fn, 0.0);
  EXPECT_EQ(h.shear[0], 0.0);
  EXPECT_EQ(h.twist, 0.0);
}

TEST(RaceContact3d, ABallPastTheCircleIsFlaggedNotForced)
{
  const RaceContactModel3d m = model(RaceSide::Inner);
  const TorusGroove g = groove(RaceSide::Inner);
  // Beyond the inner circle: the ball overlaps the tube surface from the wrong side.
  History h;
  const auto r = ohmdem::race_contact_3d(m, RingMotion3d{}, ball({g.centre_radius + 1e-3, 0, 0}),
                                         0.0, 0.0, false, h.view());
  EXPECT_TRUE(r.off_groove);
  EXPECT_EQ(r.fn, 0.0);
}

TEST(RaceContact3d, RollingRelaxesTheSpringsIntoALinearCreepLaw)
{
  // A ball rolls without slip on a turning ring (its spin matches the ring's surface speed V at
  // the contact) while it slides across the groove at v_s: the spring settles where its
  // relaxation (V / 2b) s balances the slip, s = 2b v_s / V, F_t = k_t 2b v_s / V (mu large:
  // below Coulomb). At rest the same slip would load the spring without bound.
  const RaceContactModel3d m = model(RaceSide::Outer, 1.0, 10.0);
  const double delta = 4e-6, w_ring = -50.0, v_s = 1e-4, dt = 1e-7;
  BallState3d b = ball(ball_at(RaceSide::Outer, 0.0, 0.0, delta));
  const double lever = kRb - 0.5 * delta, R = kRext + 0.5 * delta;  // contact point at x = R
  b.omega = {0.0, 0.0, w_ring * R / lever};
  b.v = {0.0, 0.0, v_s};
  RingMotion3d ring;
  ring.omega = {0.0, 0.0, w_ring};
  History h;
  ohmdem::RaceContactResult3d r;
  for (int k = 0; k < 100000; ++k) r = ohmdem::race_contact_3d(m, ring, b, 0.0, dt, true, h.view());
  const auto s = ohmdem::torus_curvatures(groove(RaceSide::Outer), 1.0);
  const auto j = ohmdem::test::johnson_hertz(s.A, s.B, kEstar, r.fn);
  const double V = std::fabs(w_ring) * R;
  const double kt = 8 * kGstar * std::sqrt(j.a * j.b);
  // (V also holds the slip's own half, v_s/2 across: 1e-9 of V here.)
  EXPECT_NEAR(-r.force_on_ball.z / (kt * 2 * j.b * v_s / V), 1.0, 1e-6);
  EXPECT_NEAR(r.ft_rolling, 0.0, 1e-9 * r.fn);
  // Not rolling, the spring keeps nearly all the slip puts in (only the patch's own travel,
  // v_s/2 over 2b, relaxes it): after the same time it holds v_s t, within 0.2 %.
  RingMotion3d rest;
  BallState3d b0 = ball(b.x);
  b0.v = b.v;
  History h0;
  for (int k = 0; k < 100000; ++k)
    r = ohmdem::race_contact_3d(m, rest, b0, 0.0, dt, true, h0.view());
  EXPECT_NEAR(h0.shear[2] / (v_s * 100000 * dt), 1.0, 2e-3);
}
