// SPDX-License-Identifier: GPL-2.0-or-later
// Unit tests of the Hertz contact kernel against independent references: scipy (via
// make_reference.py -> hertz_reference.inc), Johnson's closed forms, std::comp_ellint_*.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "conduction/conductance_laws.h"
#include "contact/hertz_contact.h"
#include "test_constants.h"

namespace {

struct RefCase {
  double A, B, kappa, a, b, delta;
};
struct Ref6208 {
  double A, B, kappa, a, b, delta, K;
  double kappa_gw, a_gw, b_gw;
};
#include "hertz_reference.inc"

using namespace ohmdem;

// SKF 6208 (paper Tables 1-2, doc/methods/hertz_contact.md "SKF 6208").
constexpr double kRb = 6.3e-3, kRinn = 24e-3, kRext = 36.6e-3, kRcInn = 6.55e-3, kRcExt = 6.65e-3;
const double kEstar = effective_modulus(200e9, 0.3, 200e9, 0.3);

double rel(double x, double ref)
{
  return std::fabs(x / ref - 1);
}

void expect_finite(const ContactEllipse &e)
{
  EXPECT_TRUE(std::isfinite(e.a) && std::isfinite(e.b) && std::isfinite(e.c) &&
              std::isfinite(e.area));
}

TEST(HertzGeometry, CurvatureSumsAndModuli)
{
  const CurvatureSums in = ball_inner_race(kRb, kRinn, kRcInn);
  EXPECT_DOUBLE_EQ(in.A, 1 / kRb + 1 / kRinn);
  EXPECT_DOUBLE_EQ(in.B, 1 / kRb - 1 / kRcInn);
  const CurvatureSums out = ball_outer_race(kRb, kRext, kRcExt);
  EXPECT_DOUBLE_EQ(out.A, 1 / kRb - 1 / kRext);
  EXPECT_DOUBLE_EQ(out.B, 1 / kRb - 1 / kRcExt);
  // Same numbers as the scipy script (which builds them independently).
  EXPECT_LT(rel(in.A, kRefInner.A), 1e-15);
  EXPECT_LT(rel(out.B, kRefOuter.B), 1e-15);
  EXPECT_DOUBLE_EQ(sphere_sphere(2.0, 3.0).A, 1 / 2.0 + 1 / 3.0);
  EXPECT_DOUBLE_EQ(sphere_flat(2.0).B, 0.5);
  // 1/E* = 2 (1 - 0.09)/200e9 for steel on steel.
  EXPECT_LT(rel(kEstar, kRefEStar), 1e-15);
  // LIGGGHTS' G*: 1/G* = 2 (2-nu)(1+nu)/E per body -> 200e9 / (4 * 1.7 * 1.3).
  EXPECT_LT(rel(effective_shear_modulus(200e9, 0.3, 200e9, 0.3), 200e9 / (4 * 1.7 * 1.3)), 1e-15);
}

// The AGM kernel against libstdc++'s comp_ellint_1/2 (which take the modulus k = sqrt(m)),
// and near m = 1, where k = sqrt(m) rounds and std loses digits, against scipy's ellipkm1.
TEST(HertzGeometry, EllipticIntegralsMatchStdAndScipy)
{
  for (double m : {1e-8, 1e-3, 0.1, 0.5, 0.9, 0.999}) {
    const double kp = std::sqrt(1 - m), k = std::sqrt(m);
    const CompleteElliptic ce = complete_elliptic(kp);
    const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
    EXPECT_LT(rel(ce.K, K), 1e-13) << "m = " << m;
    EXPECT_LT(rel(ce.E, E), 1e-13) << "m = " << m;
    if (m >= 0.1) {
      EXPECT_LT(rel(ce.D, (K - E) / m), 1e-12) << "m = " << m;
    }
  }
  for (const auto &r : kRefEllipticNearOne) {
    const CompleteElliptic ce = complete_elliptic(std::sqrt(r[0]));
    EXPECT_LT(rel(ce.K, r[1]), 1e-14) << "1 - m = " << r[0];
    EXPECT_LT(rel(ce.E, r[2]), 1e-14) << "1 - m = " << r[0];
  }
  // D = (K - E)/m -> pi/4 (1 + 3m/8) for small m (series of K and E, A&S 17.3.11-12).
  EXPECT_LT(rel(complete_elliptic(std::sqrt(1 - 1e-9)).D, test::kPi / 4 * (1 + 3e-9 / 8)), 1e-14);
  EXPECT_DOUBLE_EQ(complete_elliptic(1.0).K, test::kPi / 2);
  EXPECT_TRUE(std::isinf(complete_elliptic(0.0).K));
}

// Exact mode vs Johnson's Hertz solution computed with scipy (make_reference.py).
TEST(HertzExact, MatchesJohnsonScipyReference)
{
  double worst = 0;
  for (const RefCase &r : kRefCases) {
    for (bool swap : {false, true}) {  // the solution must not depend on which sum is A
      const CurvatureSums s = swap ? CurvatureSums{r.B, r.A} : CurvatureSums{r.A, r.B};
      const HertzContact hc(s, kRefEStar, AreaModel::Exact);
      const ContactEllipse e = hc.ellipse(kRefLoad);
      const double ratio = r.B / r.A;
      const double errs[] = {rel(hc.ellipticity(), r.kappa),
                             rel(e.a, r.a),
                             rel(e.b, r.b),
                             rel(hc.approach(kRefLoad), r.delta),
                             rel(e.area, test::kPi * r.a * r.b),
                             rel(e.c, std::sqrt(r.a * r.b))};
      for (double err : errs) {
        EXPECT_LT(err, 1e-6) << "curvature ratio " << ratio;
        // Away from ratio 1 (where scipy's K - E cancels) both sides agree to rounding.
        if (ratio >= 1.01) {
          EXPECT_LT(err, 1e-12) << "curvature ratio " << ratio;
        }
        worst = std::fmax(worst, err);
      }
      EXPECT_EQ(hc.major_axis_in_A_plane(), !swap || ratio == 1);
    }
  }
  std::printf("exact vs scipy/Johnson: worst relative error %.2e\n", worst);
}

// Johnson eqs 4.22-4.23: a = (3 Q R*/(4 E*))^(1/3), delta = a^2/R*, Q = (4/3) E* R*^0.5 d^1.5.
TEST(HertzExact, SphereSphereClosedForm)
{
  const double r1 = 5e-3, r2 = 8e-3, Rs = r1 * r2 / (r1 + r2), Q = 50;
  const double Es = effective_modulus(200e9, 0.3, 70e9, 0.33);
  const double a = std::cbrt(3 * Q * Rs / (4 * Es));
  for (AreaModel model : {AreaModel::Exact, AreaModel::Greenwood}) {
    const HertzContact hc(sphere_sphere(r1, r2), Es, model);
    EXPECT_EQ(hc.ellipticity(), 1.0);
    const ContactEllipse e = hc.ellipse(Q);
    EXPECT_LT(rel(e.a, a), 1e-14);
    EXPECT_LT(rel(e.b, a), 1e-14);
    EXPECT_LT(rel(e.area, test::kPi * a * a), 1e-14);
    EXPECT_LT(rel(hc.approach(Q), a * a / Rs), 1e-14);
    EXPECT_LT(rel(hc.stiffness_constant(), 4.0 / 3.0 * Es * std::sqrt(Rs)), 1e-14);
  }
  const HertzContact flat(sphere_flat(r1), Es);
  EXPECT_LT(rel(flat.ellipse(Q).a, std::cbrt(3 * Q * r1 / (4 * Es))), 1e-14);
}

TEST(HertzForceLaw, RoundTripAndStiffness)
{
  const HertzContact hc(ball_inner_race(kRb, kRinn, kRcInn), kEstar);
  for (double Q : {1e-12, 1e-3, 1.0, 320.0 / 13, 1e3, 1e6}) {
    EXPECT_LT(rel(hc.force(hc.approach(Q)), Q), 1e-14) << "Q = " << Q;
    // dQ/ddelta by central differences.
    const double d = hc.approach(Q), h = 1e-6 * d;
    const double fd = (hc.force(d + h) - hc.force(d - h)) / (2 * h);
    EXPECT_LT(rel(hc.normal_stiffness(d), fd), 1e-8) << "Q = " << Q;
  }
}

// doc/methods/hertz_contact.md "SKF 6208": inner kappa 9.42, outer 5.97; K_inner 3.10e10,
// K_outer 2.94e10 N/m^1.5.
TEST(Hertz6208, EllipticityAndStiffnessConstant)
{
  const HertzContact in(ball_inner_race(kRb, kRinn, kRcInn), kEstar);
  const HertzContact out(ball_outer_race(kRb, kRext, kRcExt), kEstar);
  EXPECT_NEAR(in.ellipticity(), 9.42, 0.01);
  EXPECT_NEAR(out.ellipticity(), 5.97, 0.01);
  EXPECT_LT(rel(in.stiffness_constant(), 3.10e10), 0.01);
  EXPECT_LT(rel(out.stiffness_constant(), 2.94e10), 0.01);
  // And against the scipy reference (Q / delta^1.5 from Johnson's approach).
  EXPECT_LT(rel(in.stiffness_constant(), kRefInner.K), 1e-9);
  EXPECT_LT(rel(out.stiffness_constant(), kRefOuter.K), 1e-9);
  std::printf("6208 inner: kappa %.4f K %.4e N/m^1.5 | outer: kappa %.4f K %.4e N/m^1.5\n",
              in.ellipticity(), in.stiffness_constant(), out.ellipticity(),
              out.stiffness_constant());
}

// Greenwood (paper eqs 2-5) vs exact for the 6208. doc/methods/hertz_contact.md "SKF 6208":
// S +2.5 % (inner), +1.2 % (outer); ellipticity +9 % and +5 %; rolling-direction half-width b
// about -3 %.
TEST(Hertz6208, GreenwoodVsExactTable)
{
  struct Row {
    const char *name;
    CurvatureSums s;
    const Ref6208 &ref;
    double area_pct, kappa_pct;
  };
  const Row rows[] = {{"inner", ball_inner_race(kRb, kRinn, kRcInn), kRefInner, 2.5, 9.4},
                      {"outer", ball_outer_race(kRb, kRext, kRcExt), kRefOuter, 1.2, 5.1}};
  std::printf("SKF 6208, greenwood vs exact (independent of load):\n");
  std::printf("%-6s %8s %8s %9s %9s %9s %9s\n", "race", "kappa_ex", "kappa_gw", "dS %", "dkappa %",
              "da %", "db %");
  for (const Row &r : rows) {
    const HertzContact ex(r.s, kEstar, AreaModel::Exact);
    const HertzContact gw(r.s, kEstar, AreaModel::Greenwood);
    EXPECT_EQ(gw.stiffness_constant(), ex.stiffness_constant());  // force law always exact
    EXPECT_EQ(gw.kappa_exact(), ex.ellipticity());
    const ContactEllipse e = ex.ellipse(kRefLoad), g = gw.ellipse(kRefLoad);
    // Greenwood values against the scipy script's independent evaluation.
    EXPECT_LT(rel(gw.ellipticity(), r.ref.kappa_gw), 1e-12);
    EXPECT_LT(rel(g.a, r.ref.a_gw), 1e-12);
    EXPECT_LT(rel(g.b, r.ref.b_gw), 1e-12);
    const double dS = 100 * (g.area / e.area - 1),
                 dk = 100 * (gw.ellipticity() / ex.ellipticity() - 1);
    const double da = 100 * (g.a / e.a - 1), db = 100 * (g.b / e.b - 1);
    std::printf("%-6s %8.4f %8.4f %+9.2f %+9.2f %+9.2f %+9.2f\n", r.name, ex.ellipticity(),
                gw.ellipticity(), dS, dk, da, db);
    EXPECT_NEAR(dS, r.area_pct, 0.1) << r.name;
    EXPECT_NEAR(dk, r.kappa_pct, 0.3) << r.name;
    EXPECT_LT(db, 0) << r.name;
    EXPECT_GT(db, -3.5) << r.name;
  }
}

// Holm: R = rho K(e^2)/(pi a); rho/(2a) for a circle.
TEST(HertzHolm, CircleLimitAndEllipse)
{
  const double rho = 1 / 5.88e7, a = 1e-4;
  EXPECT_LT(rel(holm_resistance(rho, a, a), rho / (2 * a)), 1e-15);
  // scipy: rho ellipk(1 - b^2/a^2)/(pi a) (make_reference.py).
  EXPECT_LT(rel(holm_resistance(kRefHolm[0], kRefHolm[1], kRefHolm[2]), kRefHolm[3]), 1e-13);
  EXPECT_EQ(holm_resistance(kRefHolm[0], kRefHolm[2], kRefHolm[1]),
            holm_resistance(kRefHolm[0], kRefHolm[1], kRefHolm[2]));  // axes in any order
  EXPECT_TRUE(std::isinf(holm_resistance(rho, 0, 0)));
  EXPECT_TRUE(std::isinf(holm_resistance(rho, a, 0)));  // a line: K(1) diverges
  EXPECT_TRUE(std::isinf(holm_resistance(rho, -a, -a)));
  EXPECT_TRUE(std::isinf(holm_resistance(rho, std::nan(""), a)));
}

TEST(HertzHardCases, NoForceNoNaN)
{
  for (AreaModel model : {AreaModel::Exact, AreaModel::Greenwood}) {
    const HertzContact hc(ball_outer_race(kRb, kRext, kRcExt), kEstar, model);
    for (double fn : {0.0, -0.0, -1.0, -1e6, std::nan("")}) {
      const ContactEllipse e = hc.ellipse(fn);
      EXPECT_EQ(e.a, 0);
      EXPECT_EQ(e.b, 0);
      EXPECT_EQ(e.c, 0);
      EXPECT_EQ(e.area, 0);
      EXPECT_EQ(hc.approach(fn), 0);
      EXPECT_EQ(hc.force(fn * 1e-6), 0);
      EXPECT_EQ(hc.normal_stiffness(fn * 1e-6), 0);
    }
    // Tiny and huge forces: finite, and the axes scale exactly as Q^(1/3).
    const ContactEllipse ref = hc.ellipse(1.0);
    for (double fn : {1e-12, 1e6, 1e300}) {
      const ContactEllipse e = hc.ellipse(fn);
      expect_finite(e);
      EXPECT_GT(e.b, 0);
      EXPECT_LT(rel(e.a, ref.a * std::cbrt(fn)), 1e-14);
      EXPECT_TRUE(std::isfinite(hc.approach(fn)));
      EXPECT_GT(hc.approach(fn), 0);
    }
  }
}

// Extreme but valid curvature ratios: the solver stays bracketed and kappa is monotone.
TEST(HertzHardCases, ExtremeCurvatureRatios)
{
  double prev = 1;
  for (double ratio : {1 + 1e-15, 1 + 1e-9, 1.5, 1e3, 1e6, 1e9, 1e12}) {
    const double k = exact_ellipticity({1.0, ratio});
    EXPECT_TRUE(std::isfinite(k)) << ratio;
    EXPECT_GE(k, prev) << ratio;
    prev = k;
    const HertzContact hc({1.0, ratio}, kEstar);
    expect_finite(hc.ellipse(1.0));
    EXPECT_TRUE(std::isfinite(hc.stiffness_constant()));
  }
}

void expect_throw_with(const std::function<void()> &f, const std::string &needle)
{
  try {
    f();
    ADD_FAILURE() << "no exception, expected one mentioning '" << needle << "'";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(HertzHardCases, InvalidInputThrowsClearly)
{
  // Groove radius equal to / smaller than the ball radius: B = 0 / B < 0.
  expect_throw_with([] { HertzContact(ball_inner_race(kRb, kRinn, kRb), kEstar); },
                    "curvature sum B");
  expect_throw_with([] { HertzContact(ball_inner_race(kRb, kRinn, 6e-3), kEstar); }, "groove");
  // Outer race radius smaller than the ball radius: A < 0.
  expect_throw_with([] { HertzContact(ball_outer_race(kRb, 5e-3, kRcExt), kEstar); },
                    "curvature sum A");
  expect_throw_with([] { HertzContact(sphere_flat(kRb), 0.0); }, "effective modulus");
  expect_throw_with([] { HertzContact(sphere_flat(kRb), -1.0); }, "must be positive");
  expect_throw_with([] { HertzContact(sphere_flat(0.0), kEstar); }, "not positive");
  expect_throw_with([] { exact_ellipticity({std::nan(""), 1.0}); }, "curvature sum A");
}

}  // namespace
