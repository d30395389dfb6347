// SPDX-License-Identifier: GPL-2.0-or-later
// The 3D raceway (src_fix/lib/contact/torus_race.*) against closed forms: the torus geometry
// (approach, contact line, contact angle, the race surface point), the curvature sums at the
// contact angle against Harris' (gamma = D cos(alpha) / dm, for a ball centre on the pitch
// circle), the exact Hertz constant and ellipse against Johnson's pressure form
// (johnson_hertz.h), and the table against the direct solution.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "contact/hertz_contact.h"
#include "contact/torus_race.h"
#include "johnson_hertz.h"
#include "test_constants.h"

namespace {

using ohmdem::AngularHertz;
using ohmdem::RaceSide;
using ohmdem::TorusGroove;
using ohmdem::Vec3;
using ohmdem::test::kPi;

// The paper's 6208 (doc/methods/hertz_contact.md): ball radius, races at the groove bottom, grooves.
constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
constexpr double kE = 200e9, kNu = 0.3;
constexpr double kEstar = kE / (2 * (1 - kNu * kNu));
constexpr double kGstar = kE / (4 * (2 - kNu) * (1 + kNu));
constexpr double kGt = kE / (4 * (1 + kNu));  // 1/(1/G + 1/G), G = E/(2(1+nu))

// An angular-contact construction (curvature centres on the alpha0 line through a ball centre
// on the pitch circle, race_grooves.h), so that Harris' curvature formulas hold exactly.
TorusGroove groove(RaceSide side, double alpha0)
{
  const bool inner = side == RaceSide::Inner;
  const double Rc = inner ? kRcInn : kRcExt, R = inner ? kRinn : kRext, s = inner ? 1.0 : -1.0;
  TorusGroove g;
  g.side = side;
  g.ball_radius = kRb;
  g.groove_radius = Rc;
  g.centre_radius = R + s * (kRb + (Rc - kRb) * std::cos(alpha0));
  g.centre_z = s * (Rc - kRb) * std::sin(alpha0);
  return g;
}

Vec3 on_line(const TorusGroove &g, double phi, double alpha, double d)
{
  // From the circle's point at azimuth phi, along m at the contact angle alpha (the inner
  // race's m points to the axis and -z for alpha > 0, the outer's away and +z).
  const double s = g.side == RaceSide::Inner ? -1.0 : 1.0;
  const double rho = g.centre_radius + s * d * std::cos(alpha);
  return {rho * std::cos(phi), rho * std::sin(phi), g.centre_z + s * d * std::sin(alpha)};
}

}  // namespace

TEST(TorusRace, GeometryAlongTheContactLine)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const TorusGroove g = groove(side, 0.0);
    for (double alpha : {-0.5, 0.0, 0.2, 0.7, 1.2}) {
      const double delta = 4e-6, d = g.groove_radius - kRb + delta, phi = 2.1;
      const auto t = ohmdem::torus_geometry(g, on_line(g, phi, alpha, d));
      ASSERT_TRUE(t.defined);
      EXPECT_NEAR(t.delta, delta, 1e-16);
      EXPECT_NEAR(t.cos_alpha, std::cos(alpha), 1e-13);
      EXPECT_NEAR(t.sin_alpha, std::sin(alpha), 1e-13);
      EXPECT_NEAR(t.e_rho.x, std::cos(phi), 1e-15);
      const double s = side == RaceSide::Inner ? -1.0 : 1.0;
      EXPECT_NEAR(t.point_radius, g.centre_radius + s * g.groove_radius * std::cos(alpha), 1e-16);
      // m is the unit vector from the circle point to the ball centre.
      EXPECT_NEAR(t.m.z, s * std::sin(alpha), 1e-13);
      EXPECT_NEAR(t.m.x * t.m.x + t.m.y * t.m.y + t.m.z * t.m.z, 1.0, 1e-15);
    }
  }
}

TEST(TorusRace, InThePlaneTheApproachIsThePlanarOne)
{
  // At alpha = 0 the torus is the planar groove: delta = R + r - rho (inner), rho + r - R.
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const bool inner = side == RaceSide::Inner;
    const TorusGroove g = groove(side, 0.0);
    const double R = inner ? kRinn : kRext, rho = inner ? R + kRb - 3e-6 : R - kRb + 3e-6;
    const auto t = ohmdem::torus_geometry(g, {rho * 0.6, rho * 0.8, 0.0});
    EXPECT_NEAR(t.delta, 3e-6, 1e-17);
    EXPECT_EQ(t.cos_alpha, 1.0);
    EXPECT_EQ(t.sin_alpha, 0.0);
    EXPECT_NEAR(t.point_radius, R, 1e-17);
  }
}

TEST(TorusRace, OnTheAxisOrOnTheCircleNoContactIsDefined)
{
  const TorusGroove g = groove(RaceSide::Inner, 0.0);
  EXPECT_FALSE(ohmdem::torus_geometry(g, {0.0, 0.0, 1e-3}).defined);
  EXPECT_FALSE(ohmdem::torus_geometry(g, {g.centre_radius, 0.0, g.centre_z}).defined);
  // Past the circle (radially outside the inner ring's circle): cos(alpha) < 0.
  const auto t = ohmdem::torus_geometry(g, {g.centre_radius + 1e-4, 0.0, 0.0});
  EXPECT_LT(t.cos_alpha, 0.0);
}

TEST(TorusRace, CurvatureSumsAreHarrisAtTheContactAngle)
{
  // Harris (Rolling Bearing Analysis, ch. 2): with gamma = D cos(alpha)/dm, the full sums are
  // inner (2/D)(2 + gamma/(1-gamma) - 1/(2 f_i)), outer (2/D)(2 - gamma/(1+gamma) - 1/(2 f_o)),
  // f = Rc/D; the ball centre on the pitch circle dm = Dinn + D.
  const double D = 2 * kRb, dm = 2 * kRinn + D;
  for (double alpha_deg : {0.0, 10.0, 25.0, 40.0}) {
    const double alpha = alpha_deg * kPi / 180;
    const double gamma = D * std::cos(alpha) / dm;
    for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
      const bool inner = side == RaceSide::Inner;
      const double f = (inner ? kRcInn : kRcExt) / D;
      const double harris =
          2 / D * (2 + (inner ? gamma / (1 - gamma) : -gamma / (1 + gamma)) - 1 / (2 * f));
      const auto s = ohmdem::torus_curvatures(groove(side, alpha), std::cos(alpha));
      EXPECT_NEAR((s.A + s.B) / harris, 1.0, 1e-13) << alpha_deg;
      EXPECT_NEAR(s.B, 1 / kRb - 1 / (inner ? kRcInn : kRcExt), 1e-10);
    }
  }
}

TEST(TorusRace, ExactHertzAtTheContactAngleAgainstJohnson)
{
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const AngularHertz h(groove(side, 0.3), kEstar, kGstar, kGt);
    for (double alpha_deg : {0.0, 5.0, 17.0, 33.0, 45.0, 60.0}) {
      const double c = std::cos(alpha_deg * kPi / 180);
      const auto s = ohmdem::torus_curvatures(h.groove(), c);
      const auto j = ohmdem::test::johnson_hertz(s.A, s.B, kEstar, 1.0);
      const auto v = h.at(c);
      EXPECT_NEAR(v.K / ohmdem::test::johnson_stiffness(s.A, s.B, kEstar), 1.0, 1e-9);
      EXPECT_NEAR(v.a1 / j.a, 1.0, 1e-9) << alpha_deg;
      EXPECT_NEAR(v.b1 / j.b, 1.0, 1e-9) << alpha_deg;
      // The full-sliding spin moment 3 mu Q a E(e)/8 at mu = 1, Q = 1 N (Harris).
      EXPECT_NEAR(v.spin_coef / (3 * j.a * j.E_ecc / 8), 1.0, 1e-9);
      // Greenwood's (1985) equivalent radius: a b = (3 Q r_eff / (4 E*))^(2/3).
      const double r_eff = std::cbrt(2 / (s.A * s.B * (s.A + s.B)));
      EXPECT_NEAR(v.a1_greenwood * v.b1_greenwood / std::pow(3 * r_eff / (4 * kEstar), 2.0 / 3),
                  1.0, 1e-9);
      // Mindlin: k_t = 8 G* sqrt(ab) at Q = K delta^1.5; torsion (16/3) G_t (ab)^(3/2).
      const double delta = 2e-6, Q = v.K * std::pow(delta, 1.5);
      const auto jq = ohmdem::test::johnson_hertz(s.A, s.B, kEstar, Q);
      EXPECT_NEAR(v.kt_coef * std::sqrt(delta) / (8 * kGstar * std::sqrt(jq.a * jq.b)), 1, 1e-8);
      EXPECT_NEAR(
          v.torsion_coef * std::pow(delta, 1.5) / (16.0 / 3 * kGt * std::pow(jq.a * jq.b, 1.5)), 1,
          1e-8);
    }
  }
}

TEST(TorusRace, TheTableFollowsTheDirectSolution)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (RaceSide side : {RaceSide::Inner, RaceSide::Outer}) {
    const AngularHertz h(groove(side, 0.0), kEstar, kGstar, kGt);
    double worst = 0;
    for (int k = 0; k < 400; ++k) {
      const double c = k < 2 ? static_cast<double>(k) : u(gen);
      const auto t = h.at(c), e = h.exact(c);
      for (double pair : {t.K / e.K, t.a1 / e.a1, t.b1 / e.b1, t.a1_greenwood / e.a1_greenwood,
                          t.spin_coef / e.spin_coef, t.torsion_coef / e.torsion_coef})
        worst = std::fmax(worst, std::fabs(pair - 1));
      // The step's values: 2b and the spin cap at Q = K delta^1.5 without a cube root.
      const auto m = h.mechanics(c);
      const double k3 = std::cbrt(e.K);
      for (double pair :
           {m.K / e.K, m.kt_coef / e.kt_coef, m.length_coef / (2 * e.b1 * k3),
            m.spin_cap_coef / (e.spin_coef * e.K * k3), m.torsion_coef / e.torsion_coef})
        worst = std::fmax(worst, std::fabs(pair - 1));
    }
    EXPECT_LT(worst, 1e-10);
  }
}

TEST(TorusRace, ImpossibleGroovesAreRefused)
{
  TorusGroove g = groove(RaceSide::Inner, 0.0);
  g.groove_radius = kRb;
  EXPECT_THROW(AngularHertz(g, kEstar, kGstar, kGt), std::invalid_argument);
  g = groove(RaceSide::Inner, 0.0);
  EXPECT_THROW(AngularHertz(g, kEstar, 0.0, kGt), std::invalid_argument);
  g.centre_radius = g.groove_radius + 0.5 * kRb;  // the groove bottom inside the ball
  EXPECT_THROW(AngularHertz(g, kEstar, kGstar, kGt), std::invalid_argument);
}
