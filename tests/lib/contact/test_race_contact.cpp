// SPDX-License-Identifier: GPL-2.0-or-later
// The ball–race contact kernel (src_fix/lib/contact/race_contact.*) against references written
// here from theory, not from the kernel's own formulas: the elliptic Hertz solution in
// Johnson's pressure form with libstdc++'s elliptic integrals (the kernel uses the ellipticity
// form and its own AGM, doc/methods/hertz_contact.md), the groove's geometry (approach, contact
// point, normal), Mindlin's tangential stiffness, the Coulomb limit, rolling without slip and the
// restitution damping of LIGGGHTS' Hertz model (contact/damping.h).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/race_contact.h"
#include "test_constants.h"

namespace {

using ohmdem::RaceContactModel;
using ohmdem::RaceContactResult;
using ohmdem::RaceContactState;
using ohmdem::RaceSide;
using ohmdem::Vec2;
using ohmdem::test::kPi;

// SKF 6208 (doc/methods/hertz_contact.md "SKF 6208"): ball radius, race radii at the groove bottom,
// groove radii (m). Steel on steel, E = 200 GPa, nu = 0.3: 1/E* = 2 (1 - nu^2)/E
// (doc/methods/hertz_contact.md "Inputs") and, in LIGGGHTS' convention,
// 1/G* = 2 * 2 (2 - nu)(1 + nu)/E (contact/hertz_contact.h).
constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
constexpr double kEstar = 200e9 / (2 * (1 - 0.3 * 0.3));
constexpr double kGstar = 200e9 / (4 * (2 - 0.3) * (1 + 0.3));
constexpr double kMass = 7850 * 4.0 / 3.0 * kPi * kRb * kRb * kRb;  // steel ball (kg)
constexpr double kMu = 0.1;

// Elliptic Hertz contact from the pressure p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) on an ellipse of
// eccentricity e (m = e^2 = 1 - b^2/a^2), for the half curvature sums A' <= B' (Johnson's
// elliptical contact, the solution doc/methods/hertz_contact.md cites):
//   A' = p0 b (K - E) / (E* m a^2),   B' = p0 b (E / (1 - m) - K) / (E* m a^2),
//   delta = p0 b K / E*,   P = (2/3) pi a b p0,
// with K(e), E(e) the complete elliptic integrals of modulus e. A sphere (m -> 0) gives back
// a^3 = 3 P R / (4 E*) and delta = a^2 / R.
struct HertzRef {
  double a, b, delta;
};

HertzRef hertz_reference(double sum1, double sum2, double Estar, double P)
{
  const double A = 0.5 * std::fmin(sum1, sum2), B = 0.5 * std::fmax(sum1, sum2);
  // B'/A' = ((a/b)^2 E - K) / (K - E), (a/b)^2 = 1/(1-m): increasing in m, bisected.
  auto ratio = [](double m) {
    const double K = std::comp_ellint_1(std::sqrt(m)), E = std::comp_ellint_2(std::sqrt(m));
    return (E / (1 - m) - K) / (K - E);
  };
  double lo = 1e-12, hi = 1 - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio(mid) < B / A ? lo : hi) = mid;
  }
  const double m = 0.5 * (lo + hi), k = std::sqrt(m);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  // From A' with p0 b = 3P/(2 pi a): a^3 = 3 P (K - E) / (2 pi E* m A').
  const double a = std::cbrt(3 * P * (K - E) / (2 * kPi * Estar * m * A));
  return {a, a * std::sqrt(1 - m), 3 * P * K / (2 * kPi * a * Estar)};
}

// The exact Hertz constant K in Q = K delta^1.5 (independent of the load).
double stiffness_reference(double sum1, double sum2, double Estar)
{
  const HertzRef h = hertz_reference(sum1, sum2, Estar, 1.0);
  return 1.0 / (h.delta * std::sqrt(h.delta));
}

// Full curvature sums of a ball in a race's groove (rolling plane, groove plane).
double rolling_sum(RaceSide side, double race_radius)
{
  return 1 / kRb + (side == RaceSide::Inner ? 1 / race_radius : -1 / race_radius);
}
double groove_sum(double groove_radius)
{
  return 1 / kRb - 1 / groove_radius;
}

RaceContactModel model(RaceSide side, double restitution = 1.0, double mu = kMu, double groove = 0,
                       double Estar = kEstar)
{
  const bool inner = side == RaceSide::Inner;
  if (groove == 0) groove = inner ? kRcInn : kRcExt;
  return RaceContactModel(side, kRb, inner ? kRinn : kRext, groove, Estar, kGstar, restitution, mu);
}

// A ball at angle phi around a race centre off the origin, at the approach delta.
constexpr double kPhi = 0.7;
const Vec2 kCentre{1e-3, -2e-3};

Vec2 unit(double phi)
{
  return {std::cos(phi), std::sin(phi)};
}

RaceContactState state(RaceSide side, double delta)
{
  const bool inner = side == RaceSide::Inner;
  const double R = inner ? kRinn : kRext;
  // inner: delta = R + rb - dist; outer: delta = dist + rb - R.
  const double dist = inner ? R + kRb - delta : R - kRb + delta;
  RaceContactState s;
  const Vec2 n = unit(kPhi);
  s.ball_x = {kCentre.x + dist * n.x, kCentre.y + dist * n.y};
  s.ball_mass = kMass;
  s.race_centre = kCentre;
  s.race_radius = R;
  return s;
}

double side_sign(RaceSide side)
{
  return side == RaceSide::Inner ? -1.0 : 1.0;  // contact on the axis side of the ball: -1
}

double rel(double x, double ref)
{
  return std::fabs(x / ref - 1);
}

}  // namespace

TEST(RaceContact, HertzForceIsKDelta15WithTheExactConstant)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const bool inner = side == RaceSide::Inner;
    const RaceContactModel m = model(side);
    const double K = stiffness_reference(rolling_sum(side, inner ? kRinn : kRext),
                                         groove_sum(inner ? kRcInn : kRcExt), kEstar);
    // doc/methods/hertz_contact.md "SKF 6208": K_hertz 3.104e10 (inner), 2.942e10 (outer) N/m^1.5.
    EXPECT_LT(rel(K, inner ? 3.104e10 : 2.942e10), 1e-3);
    for (double delta : {1e-8, 1e-7, 1e-6, 5e-6, 2e-5}) {
      double shear = 0;
      const RaceContactResult r = ohmdem::race_contact(m, state(side, delta), 1e-7, true, shear);
      ASSERT_TRUE(r.touching);
      EXPECT_NEAR(r.delta, delta, 5e-17);  // positions to a few ulp of 30 mm
      EXPECT_LT(rel(r.fn, K * r.delta * std::sqrt(r.delta)), 1e-11) << delta;
      EXPECT_EQ(r.ft, 0.0);  // nothing slides
      EXPECT_EQ(shear, 0.0);
    }
  }
}

TEST(RaceContact, TheGrooveSetsTheStiffness)
{
  // Closer conformity (groove radius nearer the ball's) flattens the contact ellipse and
  // stiffens the contact; every groove against the reference.
  double previous = 0;
  for (double groove : {1.2 * kRb, 1.08 * kRb, kRcInn, 1.02 * kRb, 1.005 * kRb}) {
    const RaceContactModel m = model(RaceSide::Inner, 1.0, kMu, groove);
    double shear = 0;
    const RaceContactResult r =
        ohmdem::race_contact(m, state(RaceSide::Inner, 1e-6), 0, false, shear);
    const double K =
        stiffness_reference(rolling_sum(RaceSide::Inner, kRinn), groove_sum(groove), kEstar);
    EXPECT_LT(rel(r.fn, K * r.delta * std::sqrt(r.delta)), 1e-11) << groove;
    EXPECT_GT(r.fn, previous) << groove;
    previous = r.fn;
  }
}

TEST(RaceContact, ApproachNormalAndContactPointOfTheGroove)
{
  const double delta = 3e-6;
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const bool inner = side == RaceSide::Inner;
    const double R = inner ? kRinn : kRext;
    double shear = 0;
    const RaceContactResult r =
        ohmdem::race_contact(model(side), state(side, delta), 0, false, shear);
    ASSERT_TRUE(r.touching);
    // The normal points from the race centre to the ball centre.
    EXPECT_NEAR(r.normal.x, std::cos(kPhi), 1e-15);
    EXPECT_NEAR(r.normal.y, std::sin(kPhi), 1e-15);
    // The contact point is the middle of the overlap: R - delta/2 from the centre on the
    // inner race (the ball sits outside it), R + delta/2 on the outer one.
    const double px = r.point.x - kCentre.x, py = r.point.y - kCentre.y;
    EXPECT_NEAR(std::hypot(px, py), inner ? R - delta / 2 : R + delta / 2, 1e-16);
    EXPECT_NEAR(std::atan2(py, px), kPhi, 1e-14);
    // The inner race pushes the ball away from the axis, the outer one towards it.
    const double s = inner ? 1.0 : -1.0;
    EXPECT_NEAR(r.force_on_ball.x, s * r.fn * std::cos(kPhi), 1e-12 * r.fn);
    EXPECT_NEAR(r.force_on_ball.y, s * r.fn * std::sin(kPhi), 1e-12 * r.fn);
    // A radial force has no moment about either centre.
    EXPECT_EQ(r.torque_on_ball, 0.0);
    EXPECT_NEAR(r.torque_on_race, 0.0, 1e-12 * r.fn * R);
  }
}

TEST(RaceContact, NoContactNoForceAndTheHistoryIsReset)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    for (double delta : {-1e-9, -1e-3}) {
      double shear = 1e-7;  // left over from an earlier contact
      const RaceContactResult r =
          ohmdem::race_contact(model(side), state(side, delta), 1e-7, true, shear);
      EXPECT_FALSE(r.touching);
      EXPECT_EQ(r.fn, 0.0);
      EXPECT_EQ(r.force_on_ball.x, 0.0);
      EXPECT_EQ(r.force_on_ball.y, 0.0);
      EXPECT_EQ(r.torque_on_race, 0.0);
      EXPECT_EQ(shear, 0.0);
    }
  }
  // A ball on the race axis has no normal: no contact, no NaN.
  RaceContactState s = state(RaceSide::Inner, 1e-6);
  s.ball_x = kCentre;
  double shear = 1e-7;
  const RaceContactResult r = ohmdem::race_contact(model(RaceSide::Inner), s, 1e-7, true, shear);
  EXPECT_FALSE(r.touching);
  EXPECT_EQ(r.fn, 0.0);
  EXPECT_EQ(shear, 0.0);
}

TEST(RaceContact, ARecessTakesItsDepthOffTheApproach)
{
  const RaceContactModel m = model(RaceSide::Outer);
  const double K =
      stiffness_reference(rolling_sum(RaceSide::Outer, kRext), groove_sum(kRcExt), kEstar);
  RaceContactState s = state(RaceSide::Outer, 4e-6);
  s.recess = 1e-6;
  double shear = 0;
  const RaceContactResult r = ohmdem::race_contact(m, s, 0, false, shear);
  EXPECT_NEAR(r.delta, 3e-6, 5e-17);
  EXPECT_LT(rel(r.fn, K * r.delta * std::sqrt(r.delta)), 1e-11);
  s.recess = 5e-6;  // a pit deeper than the approach: the ball does not touch
  EXPECT_FALSE(ohmdem::race_contact(m, s, 0, false, shear).touching);
}

// Mindlin: k_t = 8 G* c with c = sqrt(ab) of the contact ellipse at the current load.
TEST(RaceContact, StickingFollowsMindlinsTangentialStiffness)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const bool inner = side == RaceSide::Inner;
    const double delta = 1e-5, vt = 1e-3, dt = 1e-7;
    RaceContactState s = state(side, delta);
    const Vec2 n = unit(kPhi), t{-n.y, n.x};
    s.ball_v = {vt * t.x, vt * t.y};  // sliding along t, no spin, races still
    double shear = 0;
    const RaceContactResult r = ohmdem::race_contact(model(side), s, dt, true, shear);
    ASSERT_TRUE(r.touching);
    EXPECT_NEAR(shear, vt * dt, 1e-24);
    const HertzRef h = hertz_reference(rolling_sum(side, inner ? kRinn : kRext),
                                       groove_sum(inner ? kRcInn : kRcExt), kEstar, r.fn);
    const double kt = 8 * kGstar * std::sqrt(h.a * h.b);
    EXPECT_LT(rel(r.ft, -kt * vt * dt), 1e-9);  // restitution 1: no tangential damping
    EXPECT_LT(std::fabs(r.ft), kMu * r.fn);     // well inside the Coulomb cone
    // The force adds along t; its moment about the ball centre is (lever arm) x ft, the lever
    // pointing to the contact point (rb - delta/2 long, towards the axis on the inner race).
    const double arm = kRb - 0.5 * r.delta, sd = side_sign(side);
    EXPECT_NEAR(r.force_on_ball.x, -sd * r.fn * n.x + r.ft * t.x, 1e-12 * r.fn);
    EXPECT_NEAR(r.force_on_ball.y, -sd * r.fn * n.y + r.ft * t.y, 1e-12 * r.fn);
    EXPECT_LT(rel(r.torque_on_ball, sd * arm * r.ft), 1e-12);
    // About the race centre only ft has a moment, at the contact point's radius.
    const double rho = (inner ? kRinn - r.delta / 2 : kRext + r.delta / 2);
    EXPECT_LT(rel(r.torque_on_race, -rho * r.ft), 1e-9);
  }
}

TEST(RaceContact, SlidingStopsAtTheCoulombLimit)
{
  const RaceContactModel m = model(RaceSide::Inner);
  const RaceContactState s = state(RaceSide::Inner, 1e-5);
  for (double stretched : {1.0, -1.0}) {
    double shear = stretched;  // far beyond what the spring can hold
    const RaceContactResult r = ohmdem::race_contact(m, s, 0, false, shear);
    EXPECT_EQ(std::fabs(r.ft), kMu * r.fn);
    EXPECT_EQ(std::signbit(r.ft), stretched > 0);  // against the stretch
    // The spring keeps what the cone carries: shear = mu fn / k_t.
    const HertzRef h =
        hertz_reference(rolling_sum(RaceSide::Inner, kRinn), groove_sum(kRcInn), kEstar, r.fn);
    EXPECT_LT(rel(std::fabs(shear), kMu * r.fn / (8 * kGstar * std::sqrt(h.a * h.b))), 1e-9);
  }
  // Without friction nothing is carried tangentially.
  double shear = 1e-6;
  const RaceContactResult r =
      ohmdem::race_contact(model(RaceSide::Inner, 1.0, 0.0), s, 0, false, shear);
  EXPECT_EQ(r.ft, 0.0);
  EXPECT_EQ(shear, 0.0);
}

TEST(RaceContact, RollingWithoutSlipHasNoTangentialForce)
{
  // The inner race turns at Omega under a ball held in place (by the cage): the ball spins so
  // that its surface moves with the race at the contact point, Omega (R - delta/2) along t =
  // -omega (rb - delta/2) along t.
  const double delta = 5e-6, Omega = 100.0;
  RaceContactState s = state(RaceSide::Inner, delta);
  s.race_omega = Omega;
  s.ball_omega = -Omega * (kRinn - delta / 2) / (kRb - delta / 2);
  double shear = 0;
  const RaceContactResult r = ohmdem::race_contact(model(RaceSide::Inner), s, 1e-7, true, shear);
  ASSERT_TRUE(r.touching);
  EXPECT_LT(std::fabs(r.ft), 1e-9 * r.fn);
  // The same ball not spinning slides on the race: the spring loads against the race's motion
  // (the race drags the ball's surface along +t, the force on the ball follows it).
  s.ball_omega = 0;
  shear = 0;
  EXPECT_GT(ohmdem::race_contact(model(RaceSide::Inner), s, 1e-7, true, shear).ft, 0.0);
}

// LIGGGHTS' Hertz damping (contact/damping.h, written out here): gamma = -2 sqrt(5/6) beta
// sqrt(S m), beta = ln e / sqrt(ln^2 e + pi^2), S = dQ/ddelta = 1.5 K sqrt(delta) normally and
// k_t tangentially; the normal force never pulls (no adhesion).
TEST(RaceContact, RestitutionDampingAndNoAdhesion)
{
  const double e = 0.5, delta = 2e-6;
  const double beta = std::log(e) / std::sqrt(std::log(e) * std::log(e) + kPi * kPi);
  const RaceContactModel m = model(RaceSide::Inner, e);
  const double K =
      stiffness_reference(rolling_sum(RaceSide::Inner, kRinn), groove_sum(kRcInn), kEstar);
  const Vec2 n = unit(kPhi), t{-n.y, n.x};
  RaceContactState s = state(RaceSide::Inner, delta);
  // The ball moves towards the inner race's axis at 1 mm/s: the approach grows at 1 mm/s.
  const double rate = 1e-3, vt = 2e-3;
  s.ball_v = {-rate * n.x + vt * t.x, -rate * n.y + vt * t.y};
  double shear = 0;
  const RaceContactResult r = ohmdem::race_contact(m, s, 0, false, shear);
  const double sn = 1.5 * K * std::sqrt(r.delta);
  const double gamma_n = -2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(sn * kMass);
  EXPECT_LT(rel(r.fn, K * r.delta * std::sqrt(r.delta) + gamma_n * rate), 1e-10);
  const HertzRef h = hertz_reference(rolling_sum(RaceSide::Inner, kRinn), groove_sum(kRcInn),
                                     kEstar, K * r.delta * std::sqrt(r.delta));
  const double kt = 8 * kGstar * std::sqrt(h.a * h.b);
  const double gamma_t = -2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(kt * kMass);
  EXPECT_LT(rel(r.ft, -gamma_t * vt), 1e-9);  // no spring history: damping only
  // Leaving fast: the damping would pull, the force stops at zero.
  s.ball_v = {1e3 * n.x, 1e3 * n.y};
  const RaceContactResult away = ohmdem::race_contact(m, s, 0, false, shear);
  EXPECT_TRUE(away.touching);
  EXPECT_EQ(away.fn, 0.0);
}

TEST(RaceContact, AVeryStiffContactScalesWithTheModulus)
{
  // E* 10^4 times steel's: K and the force scale by 10^4, everything stays finite, also at an
  // approach of a millimetre.
  for (double delta : {1e-9, 1e-6, 1e-3}) {
    double s1 = 0, s2 = 0;
    const RaceContactState st = state(RaceSide::Outer, delta);
    const RaceContactResult soft = ohmdem::race_contact(model(RaceSide::Outer), st, 1e-7, true, s1);
    const RaceContactResult stiff =
        ohmdem::race_contact(model(RaceSide::Outer, 1.0, kMu, 0, 1e4 * kEstar), st, 1e-7, true, s2);
    ASSERT_TRUE(std::isfinite(stiff.fn) && std::isfinite(stiff.ft)) << delta;
    EXPECT_LT(rel(stiff.fn, 1e4 * soft.fn), 1e-12) << delta;
    const double K =
        stiffness_reference(rolling_sum(RaceSide::Outer, kRext), groove_sum(kRcExt), 1e4 * kEstar);
    EXPECT_LT(rel(stiff.fn, K * stiff.delta * std::sqrt(stiff.delta)), 1e-11) << delta;
  }
}

TEST(RaceContact, InvalidModelsThrowClearly)
{
  auto message = [](auto make) -> std::string {
    try {
      make();
    } catch (const std::invalid_argument &e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message([] { model(RaceSide::Inner, 1.0, kMu, kRb); }),
            "groove radius must be larger than the ball radius");
  EXPECT_EQ(
      message([] { RaceContactModel(RaceSide::Outer, kRb, kRb, kRcExt, kEstar, kGstar, 1, 0); }),
      "outer race radius must be larger than the ball radius");
  EXPECT_EQ(message([] { RaceContactModel(RaceSide::Inner, kRb, kRinn, kRcInn, kEstar, 0, 1, 0); }),
            "shear modulus must be positive");
  EXPECT_EQ(message([] { model(RaceSide::Inner, 1.0, -0.1); }),
            "friction coefficient must be >= 0");
  EXPECT_EQ(message([] { model(RaceSide::Inner, 0.0); }),
            "coefficient of restitution must be in (0, 1]");
}
