// SPDX-License-Identifier: GPL-2.0-or-later
// A race's contact near a pit strip (src_fix/lib/lubrication/pit_contact.*): a strip over the
// whole wetted circle is contact_admittance() with the recess over the whole circle (the
// reference of test_contact_defects.cpp); a strip that misses the Hertz zone leaves it as the
// fast path gave it; no NaN without entrainment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lubrication/contact_admittance.h"
#include "lubrication/pit_contact.h"
#include "lubrication/race_admittance.h"
#include "test_constants.h"

using namespace ohmdem::lubrication;

namespace {

// A race like the 6208's inner one in VG 68 at 40 C: Hamrock's Rx and Ry for d = 12.6 mm,
// dm = 60 mm, f = 0.52; a Hertz ellipse of k ~ 9 (0.30 mm by 0.032 mm at 15 N); the deck's
// roughness and wetted radius; VG 68's viscosity, pressure coefficient and permittivity.
RaceInput inner_race()
{
  RaceInput in;
  in.rx = 4.977e-3;
  in.ry = 0.1638;
  in.e_prime = 2.198e11;
  in.a_coef = 0.1213e-3;  // a = a_coef fn^(1/3): 0.30 mm at 15 N
  in.b_coef = 0.0130e-3;
  in.eta = 0.0589;
  in.alpha = 2.2e-8;
  in.sigma = 0.1e-6;
  in.r_wet = 1.26e-3;
  in.eps_r = 2.07;
  in.resistivity = 1e12;
  return in;
}

// contact_admittance()'s input for the same contact with a recess over the whole circle.
ContactInput reference(const RaceInput &r, double fn, double speed, double g_dry, double recess)
{
  ContactInput in;
  in.film = FilmInput{fn, speed, r.rx, r.ry, r.e_prime, r.eta, r.alpha, r.a_coef / r.b_coef};
  in.a = r.a_coef * std::cbrt(fn);
  in.b = r.b_coef * std::cbrt(fn);
  in.sigma = r.sigma;
  in.r_wet = r.r_wet;
  in.eps_r = r.eps_r;
  in.resistivity = r.resistivity;
  in.g_dry = g_dry;
  in.recess = recess;
  return in;
}

}  // namespace

TEST(PitContact, StripOverTheWholeCircleIsTheRecessOverTheWholeCircle)
{
  const RaceInput race = inner_race();
  const RaceAdmittance fast(race);
  for (const double speed : {0.0, 0.05, 7.25})
    for (const double depth : {0.2e-6, 3.5e-6}) {
      const double fn = 15.0, g_dry = 0.0;  // in the zone: no metal
      ContactAdmittance c = fast.contact(fn, speed, g_dry, 0.0);
      contact_over_pit(race, fn, 0.0, PitStrip{-2e-3, 2e-3, depth, 0.0}, c);
      const ContactAdmittance want = contact_admittance(reference(race, fn, speed, g_dry, depth));
      EXPECT_NEAR(c.c_outer / want.c_outer, 1.0, 1e-10) << speed << " " << depth;
      if (want.c_hertz > 0.0)
        EXPECT_NEAR(c.c_hertz / want.c_hertz, 1.0, 1e-10);
      else
        EXPECT_EQ(c.c_hertz, 0.0);
      EXPECT_NEAR(c.metallic, want.metallic, 1e-12);
      EXPECT_NEAR(c.gap, want.gap, 1e-18);
      EXPECT_TRUE(std::isfinite(c.g) && std::isfinite(c.c_hertz));
    }
}

TEST(PitContact, AStripAheadOfTheHertzZoneChangesOnlyTheGapAround)
{
  const RaceInput race = inner_race();
  const RaceAdmittance fast(race);
  const ContactAdmittance plain = fast.contact(15.0, 7.25, 0.3, 0.0);
  ContactAdmittance c = plain;
  contact_over_pit(race, 15.0, 0.0, PitStrip{0.5e-3, 0.92e-3, 5e-6, 6.3e-3}, c);
  EXPECT_EQ(c.c_hertz, plain.c_hertz);
  EXPECT_EQ(c.g, plain.g);
  EXPECT_EQ(c.metallic, plain.metallic);
  EXPECT_EQ(c.gap, plain.gap);
  EXPECT_LT(c.c_outer, plain.c_outer);
  EXPECT_GT(c.c_outer, 0.9 * plain.c_outer);
  // Outside the circle: the fast path's c_outer within its budget (1e-10 relative).
  ContactAdmittance far = plain;
  contact_over_pit(race, 15.0, 0.0, PitStrip{1.3e-3, 1.72e-3, 5e-6, 6.3e-3}, far);
  EXPECT_NEAR(far.c_outer / plain.c_outer, 1.0, 1e-10);
}

TEST(PitContact, AStripOverTheHertzZoneWidensItsFilmThere)
{
  // The 1 deg inner pit centred under a 15 N contact (2b = 0.064 mm inside the 0.42 mm strip):
  // the Hertz zone sees h_c + r(x), r rounded by the ball (sag 3.5 um at the centre).
  const RaceInput race = inner_race();
  const RaceAdmittance fast(race);
  const ContactAdmittance plain = fast.contact(15.0, 7.25, 0.0, 0.0);
  ContactAdmittance c = plain;
  contact_over_pit(race, 15.0, 0.0, PitStrip{-0.21e-3, 0.21e-3, 5e-6, 6.3e-3}, c);
  // The smallest r over the ellipse is at its ends x = +-b, the ball's sag 0.21 mm - b from
  // the edge; the film there and at the centre bound the Hertz zone's capacitance (no metal at
  // lambda ~ 11, the same permittivity).
  const auto sag = [](double d) { return 6.3e-3 - std::sqrt(6.3e-3 * 6.3e-3 - d * d); };
  const double b = race.b_coef * std::cbrt(15.0), hc = plain.film.central;
  EXPECT_NEAR(c.gap / (plain.gap + sag(0.21e-3 - b)), 1.0, 1e-12);
  EXPECT_LT(c.c_hertz, plain.c_hertz * hc / (hc + sag(0.21e-3 - b)));
  EXPECT_GT(c.c_hertz, plain.c_hertz * hc / (hc + sag(0.21e-3)));
  EXPECT_LT(c.c_outer, plain.c_outer);
}

TEST(PitContact, AnIdleGapOverAStrip)
{
  // Nothing excluded: a strip over the whole circle is idle_gap_capacitance at
  // max(gap, sigma) + depth (the roughness floor is the nominal surface's, the pit adds to it,
  // as for a loaded contact); a narrow one under the ball takes less off.
  const RaceInput race = inner_race();
  for (const double gap : {0.0, 2e-6, 50e-6}) {
    const double whole = idle_gap_capacitance(std::max(gap, race.sigma) + 5e-6, race.rx, race.ry,
                                              race.r_wet, race.eps_r, race.sigma);
    EXPECT_NEAR(idle_over_pit(race, gap, PitStrip{-2e-3, 2e-3, 5e-6, 0.0}) / whole, 1.0, 1e-10);
    const double none =
        idle_gap_capacitance(gap, race.rx, race.ry, race.r_wet, race.eps_r, race.sigma);
    const double narrow = idle_over_pit(race, gap, PitStrip{-0.21e-3, 0.21e-3, 5e-6, 6.3e-3});
    EXPECT_TRUE(narrow < none && narrow > whole) << gap;
  }
}
