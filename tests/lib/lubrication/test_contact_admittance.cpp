// SPDX-License-Identifier: GPL-2.0-or-later
// Contact capacitance, metallic fraction and the bearing's complex arithmetic
// (src_fix/lib/lubrication/contact_admittance.*), against closed forms and hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/hertz_contact.h"
#include "lubrication/contact_admittance.h"
#include "test_constants.h"

using namespace ohmdem::lubrication;
using ohmdem::test::kPi;

namespace {
const double kEprime = 2.0e11 / (1.0 - 0.3 * 0.3);

// The 6208 inner contact (doc/methods/hertz_contact.md) at load w and entrainment speed u.
ContactInput inner_6208(double w, double u)
{
  const ohmdem::CurvatureSums s = ohmdem::ball_inner_race(0.0063, 0.024, 0.00655);
  const ohmdem::HertzContact h(s, kEprime / 2.0);
  const ohmdem::ContactEllipse e = h.ellipse(w);
  ContactInput in;
  in.film = FilmInput{w, u, 1.0 / s.A, 1.0 / s.B, kEprime, 0.0589, 2.2e-8, e.a / e.b};
  in.a = e.a;
  in.b = e.b;
  in.sigma = 0.1e-6;
  in.r_wet = 1e-3;
  in.eps_r = 2.07;
  in.resistivity = 1e12;
  in.g_dry = 10.0;
  return in;
}
}  // namespace

TEST(ContactAdmittance, PressureRaisesThePermittivity)
{
  // At 1 GPa by hand: (2.07-1)/(2.07+2) = 0.262899, density x (1 + 0.6/2.7), c = 0.321321,
  // eps = (1 + 2c)/(1 - c) = 2.420354.
  EXPECT_NEAR(permittivity_at_pressure(2.07, 1e9), 2.420354, 1e-6);
  EXPECT_DOUBLE_EQ(permittivity_at_pressure(2.07, 0.0), 2.07);
  // Uniform pressure: the mean is the value.
  EXPECT_NEAR(hertz_mean_permittivity(2.07, 0.0), 2.07, 1e-14);
  // The mean over a Hertz ellipse lies between the rim's and the peak's.
  const double m = hertz_mean_permittivity(2.07, 1e9);
  EXPECT_GT(m, 2.07);
  EXPECT_LT(m, 2.420354);
}

TEST(ContactAdmittance, GapOfASphereOverAPlane)
{
  // Nothing excluded, rx = ry = R: C = 2 pi eps0 eps_r R ln(1 + r^2 / (2 R h)).
  const double R = 0.0063, h = 0.5e-6, r = 1e-3;
  GapGeometry g{h, R, R, 0.0, 0.0, r};
  const double exact = 2.0 * kPi * kEpsilon0 * 2.07 * R * std::log(1.0 + r * r / (2.0 * R * h));
  EXPECT_NEAR(gap_capacitance(g, 2.07) / exact, 1.0, 1e-12);
  // Elliptical gap, no exclusion, wetted region large: compare with a brute-force 2D sum.
  GapGeometry e{h, 0.005, 0.15, 0.0, 0.0, 0.5e-3};
  double sum = 0.0;
  const int n = 2000;
  const double dx = 2.0 * e.r_wet / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -e.r_wet + (i + 0.5) * dx, y = -e.r_wet + (j + 0.5) * dx;
      if (x * x + y * y <= e.r_wet * e.r_wet)
        sum += dx * dx / (h + x * x / (2 * e.rx) + y * y / (2 * e.ry));
    }
  EXPECT_NEAR(gap_capacitance(e, 1.0) / (kEpsilon0 * sum), 1.0, 2e-3);
}

TEST(ContactAdmittance, MetallicFraction)
{
  EXPECT_DOUBLE_EQ(metallic_fraction(0.0), 1.0);
  EXPECT_NEAR(metallic_fraction(1.0), 0.317311, 1e-6);  // 2 (1 - Phi(1))
  EXPECT_NEAR(metallic_fraction(3.0), 0.0026998, 1e-7);
}

TEST(ContactAdmittance, DryLimitIsTheDryConductance)
{
  ContactInput in = inner_6208(25.0, 0.0);  // no entrainment: no film, lambda 0
  const ContactAdmittance c = contact_admittance(in);
  EXPECT_EQ(c.lambda, 0.0);
  EXPECT_EQ(c.metallic, 1.0);
  EXPECT_EQ(c.g, in.g_dry);
  EXPECT_EQ(c.c_hertz, 0.0);
  // Two such contacts in series at 0 Hz: the ball's dry conductance g_dry / 2.
  EXPECT_DOUBLE_EQ(series(c.y(0.0), c.y(0.0)).real(), in.g_dry / 2.0);
}

TEST(ContactAdmittance, HertzZoneScalesAsHertzAndHamrockDowson)
{
  // C_hertz / eps_mean = eps0 pi a b / h_c: a b ~ Q^(2/3), h_c ~ Q^-0.067 u^0.67, so
  // C ~ Q^0.7333 u^-0.67 (lambda >> 3 here: the metallic fraction is below 1e-12).
  auto c_geom = [](double w, double u) {
    const ContactInput in = inner_6208(w, u);
    const ContactAdmittance c = contact_admittance(in);
    EXPECT_GT(c.lambda, 5.0);
    return c.c_hertz / hertz_mean_permittivity(in.eps_r, 1.5 * w / (kPi * in.a * in.b));
  };
  EXPECT_NEAR(std::log(c_geom(40.0, 7.0) / c_geom(10.0, 7.0)) / std::log(4.0), 2.0 / 3.0 + 0.067,
              1e-3);
  EXPECT_NEAR(std::log(c_geom(25.0, 12.0) / c_geom(25.0, 3.0)) / std::log(4.0), -0.67, 1e-9);
}

TEST(ContactAdmittance, PaperPointIsCapacitive)
{
  const ContactAdmittance c = contact_admittance(inner_6208(320.0 / 13.0, 7.25));
  EXPECT_GT(c.lambda, 3.0);
  EXPECT_GT(c.c_hertz, 1e-12);  // pF range
  EXPECT_LT(c.c_hertz, 1e-10);
  EXPECT_GT(c.c_outer, c.c_hertz);  // the gap around adds more (doc: outer-zone factor)
  const Impedance z = impedance(c.y(2.0 * kPi * 1e4), 2.0 * kPi * 1e4);
  EXPECT_NEAR(z.z_phase, -kPi / 2.0, 0.01);
}

TEST(ContactAdmittance, SeriesParallelByHand)
{
  // (2 + 3j)(1 - 1j) / (3 + 2j) = (5 + 1j)(3 - 2j) / 13 = (17 - 7j) / 13.
  const std::complex<double> s = series({2.0, 3.0}, {1.0, -1.0});
  EXPECT_NEAR(s.real(), 17.0 / 13.0, 1e-15);
  EXPECT_NEAR(s.imag(), -7.0 / 13.0, 1e-15);
  EXPECT_EQ(series(0.0, 0.0), std::complex<double>(0.0));
  // Two balls in parallel, each 1 S with 1 nF at omega = 1e6 rad/s: Y = 2 + 2e-3 j.
  const std::complex<double> ball = series({2.0, 2e-3}, {2.0, 2e-3});  // 1 + 1e-3 j
  const Impedance z = impedance(ball + ball, 1e6);
  EXPECT_NEAR(z.r_parallel, 0.5, 1e-15);
  EXPECT_NEAR(z.c_parallel, 2e-9, 1e-22);
  EXPECT_NEAR(z.z_abs, 1.0 / std::hypot(2.0, 2e-3), 1e-15);
  EXPECT_NEAR(z.z_phase, -std::atan(1e-3), 1e-15);
  // A pure capacitor.
  EXPECT_NEAR(impedance({0.0, 1e-3}, 1e6).z_phase, -kPi / 2.0, 1e-15);
  EXPECT_TRUE(std::isinf(impedance({0.0, 1e-3}, 1e6).r_parallel));
}
