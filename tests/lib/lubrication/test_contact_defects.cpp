// SPDX-License-Identifier: GPL-2.0-or-later
// A lubricated contact over a pit (ContactInput::recess) and film breakdown
// (src_fix/lib/lubrication/contact_admittance.*), against the sphere-plane closed form of the
// gap integral and hand-computed values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "lubrication/contact_admittance.h"
#include "test_constants.h"

using namespace ohmdem::lubrication;
using ohmdem::test::kPi;

namespace {
const double kEprime = 2.0e11 / (1.0 - 0.3 * 0.3);

// A circular contact (rx = ry = R, a = b): its gap outside the Hertz circle is the
// sphere-plane closed form C = 2 pi eps0 eps_r R ln((h0 + r_wet^2 / 2R) / (h0 + a^2 / 2R)).
ContactInput circular(double load, double speed)
{
  ContactInput in;
  in.film = FilmInput{load, speed, 0.00315, 0.00315, kEprime, 0.0589, 2.2e-8, 1.0};
  in.a = in.b = 0.2e-3;
  in.sigma = 0.2e-6;
  in.r_wet = 1.26e-3;
  in.eps_r = 2.07;
  in.resistivity = 1e12;
  in.g_dry = 10.0;
  return in;
}

double sphere_plane(double h0, const ContactInput &in)
{
  const double R = in.film.rx;
  return 2.0 * kPi * kEpsilon0 * in.eps_r * R *
         std::log((h0 + in.r_wet * in.r_wet / (2.0 * R)) / (h0 + in.a * in.a / (2.0 * R)));
}
}  // namespace

TEST(ContactDefects, NoRecessIsThePlainContact)
{
  ContactInput in = circular(300.0, 10.0);
  const ContactAdmittance plain = contact_admittance(in);
  in.recess = 0.0;
  const ContactAdmittance c = contact_admittance(in);
  EXPECT_EQ(c.c_hertz, plain.c_hertz);
  EXPECT_EQ(c.c_outer, plain.c_outer);
  EXPECT_EQ(c.g, plain.g);
  EXPECT_EQ(c.gap, plain.film.minimum);
  EXPECT_EQ(c.g_dry, 10.0);
}

TEST(ContactDefects, GapOverAPitAgainstTheSpherePlaneClosedForm)
{
  // No entrainment (h_c = 0), no load (the permittivity is the oil's): over a pit of recess
  // 3.5 um with sigma = 0.2 um the gap around the Hertz circle starts at h0 = 3.7 um.
  ContactInput in = circular(0.0, 0.0);
  in.recess = 3.5e-6;
  const ContactAdmittance c = contact_admittance(in);
  // 1.1740500586380897e-12 F: the closed form above evaluated in Python (math.log, CODATA
  // eps0) at R = 3.15 mm, a = 0.2 mm, r_wet = 1.26 mm, h0 = 3.7 um, eps_r = 2.07.
  EXPECT_NEAR(c.c_outer / 1.1740500586380897e-12, 1.0, 1e-12);
  EXPECT_NEAR(c.c_outer / sphere_plane(3.7e-6, in), 1.0, 1e-12);
  // The Hertz circle: a parallel plate of gap h = recess over its non-metallic part,
  // f = erfc(3.5 / 0.2 / sqrt 2) (1e-68: none).
  EXPECT_NEAR(c.c_hertz / (kEpsilon0 * 2.07 * kPi * in.a * in.a / 3.5e-6), 1.0, 1e-13);
  EXPECT_LT(c.metallic, 1e-60);
  EXPECT_DOUBLE_EQ(c.gap, 3.5e-6);
}

TEST(ContactDefects, CapacitanceCollapsesAsTheRecessGrows)
{
  // A loaded, entrained contact: the film and lambda do not change with the recess; the Hertz
  // zone's capacitance goes as 1 / (h_c + recess) (its metallic fraction, erfc(lambda/sqrt 2),
  // is below 1e-15 at lambda > 8); the gap around it follows the closed form at
  // h0 = max(h_c, sigma) + recess.
  ContactInput in = circular(300.0, 10.0);
  in.sigma = 0.05e-6;
  const ContactAdmittance c0 = contact_admittance(in);
  const double hc = c0.film.central;
  ASSERT_GT(c0.lambda, 8.0);
  EXPECT_NEAR(c0.c_outer / sphere_plane(std::max(hc, in.sigma), in), 1.0, 1e-12);
  double last = c0.capacitance();
  for (const double d : {0.5e-6, 1e-6, 2.5e-6, 5e-6}) {
    in.recess = d;
    const ContactAdmittance c = contact_admittance(in);
    EXPECT_EQ(c.film.minimum, c0.film.minimum);
    EXPECT_EQ(c.lambda, c0.lambda);
    EXPECT_NEAR(c.c_hertz / c0.c_hertz, hc / (hc + d), 1e-12);
    EXPECT_NEAR(c.c_outer / sphere_plane(std::max(hc, in.sigma) + d, in), 1.0, 1e-12);
    EXPECT_LT(c.capacitance(), last);
    last = c.capacitance();
  }
}

TEST(ContactDefects, MetalOverAPitIsThatOfTheGap)
{
  // A thin film: sigma chosen so that h_min / sigma = 0.5, f = erfc(0.5 / sqrt 2) =
  // 0.6170750774519738 (Python math.erfc); a recess of 2 sigma gives (h_min + recess) / sigma
  // = 2.5 and f = erfc(2.5 / sqrt 2) = 0.012419330651552278.
  ContactInput in = circular(300.0, 10.0);
  in.sigma = contact_admittance(in).film.minimum / 0.5;
  const ContactAdmittance thin = contact_admittance(in);
  EXPECT_NEAR(thin.metallic, 0.6170750774519738, 1e-14);
  in.recess = 2.0 * in.sigma;
  const ContactAdmittance pit = contact_admittance(in);
  EXPECT_NEAR(pit.metallic, 0.012419330651552278, 1e-14);
  EXPECT_EQ(pit.lambda, thin.lambda);  // lambda stays the film's
  EXPECT_LT(pit.g, thin.g);
}

TEST(ContactDefects, VoltageAcrossAContactInSeries)
{
  // Two capacitors in series share the charge: V1 = V C2 / (C1 + C2); 10 pF and 30 pF under
  // 2 V: 1.5 V across the 10 pF one, 0.5 V across the other.
  const double w = 2.0 * kPi * 1e4;
  const std::complex<double> y1(0.0, w * 10e-12), y2(0.0, w * 30e-12);
  EXPECT_NEAR(contact_voltage(y1, y2, 2.0), 1.5, 1e-14);
  EXPECT_NEAR(contact_voltage(y2, y1, 2.0), 0.5, 1e-14);
  // A resistor (1 S) in series with a capacitor of admittance j S: |j / (1 + j)| = 1/sqrt 2.
  EXPECT_NEAR(contact_voltage({1.0, 0.0}, {0.0, 1.0}, 1.0), std::sqrt(0.5), 1e-15);
  EXPECT_EQ(contact_voltage(0.0, 0.0, 1.0), 0.0);
}

TEST(ContactDefects, BreakdownCriterion)
{
  // 10 MV/m over 0.1 um: 1 V.
  EXPECT_TRUE(film_breaks_down(1.5, 0.1e-6, 10e6));
  EXPECT_FALSE(film_breaks_down(0.5, 0.1e-6, 10e6));
  EXPECT_FALSE(film_breaks_down(1e6, 0.1e-6, 0.0));  // field 0: breakdown off
  // A broken-down contact conducts through its whole metallic path; the gap around the Hertz
  // zone keeps its capacitance.
  const ContactAdmittance c = contact_admittance(circular(300.0, 10.0));
  const ContactAdmittance b = broken_down(c);
  EXPECT_EQ(b.g, 10.0);
  EXPECT_EQ(b.metallic, 1.0);
  EXPECT_EQ(b.c_hertz, 0.0);
  EXPECT_EQ(b.c_outer, c.c_outer);
}

TEST(ContactDefects, ABrokenContactPutsTheVoltageOnTheOther)
{
  // Two film capacitors of 10 and 30 pF, gaps of 1 um, 1 MV/m: each breaks above 1 V.
  const double w = 2.0 * kPi * 1e4;
  ContactAdmittance c[2];
  c[0].c_hertz = 10e-12;
  c[1].c_hertz = 30e-12;
  for (ContactAdmittance &k : c) k.gap = 1e-6, k.g_dry = 10.0;
  const bool loaded[2] = {true, true};
  // 1.2 V: 0.9 and 0.3 V across them (V C_other / (C1 + C2)): nothing breaks.
  std::complex<double> y[2] = {c[0].y(w), c[1].y(w)};
  EXPECT_EQ(break_down_ball(y, c, loaded, 1.2, 1e6, w), 0);
  EXPECT_EQ(y[0], c[0].y(w));
  // 1.5 V: 1.125 V breaks the 10 pF film; the 30 pF one then carries almost all 1.5 V
  // (10 S against j 1.9 uS) and breaks too, whichever order they are judged in.
  EXPECT_EQ(break_down_ball(y, c, loaded, 1.5, 1e6, w), 2);
  EXPECT_EQ(y[0], std::complex<double>(10.0, 0.0));
  EXPECT_EQ(y[1], std::complex<double>(10.0, 0.0));
  // A contact without a film (not pressed) never breaks down.
  const bool one[2] = {true, false};
  std::complex<double> z[2] = {c[0].y(w), c[1].y(w)};
  EXPECT_EQ(break_down_ball(z, c, one, 1.5, 1e6, w), 1);
  EXPECT_EQ(z[1], c[1].y(w));
}
