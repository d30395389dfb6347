// SPDX-License-Identifier: GPL-2.0-or-later
// A contact near a race pit; see pit_contact.h.
#include "lubrication/pit_contact.h"

#include <algorithm>
#include <cmath>

#include "common/constants.h"

namespace ohmdem::lubrication {

void contact_over_pit(const RaceInput &race, double fn, double rest, const PitStrip &strip,
                      ContactAdmittance &c)
{
  const double cb = std::cbrt(fn);
  const double a = race.a_coef * cb, b = race.b_coef * cb;  // as RaceAdmittance::contact
  // The Hertz zone only where the strip reaches into it: else c's own (the fast path's) stays.
  if (strip.x1 < b && strip.x2 > -b && strip.depth > 0.0) {
    const HertzFilm film{c.film.central + rest, c.film.minimum + rest, race.sigma, a, b};
    const HertzOverPit hz = hertz_over_pit(film, strip);
    c.metallic = hz.metallic;
    c.g = hz.metallic * c.g_dry;
    c.c_hertz = 0.0;
    c.gap = c.film.minimum + rest + hz.min_recess;
    if (hz.free_h > 0.0) {
      const double p0 = 1.5 * fn / (kPi * a * b);  // Hertz peak pressure
      c.c_hertz = kEpsilon0 * hertz_mean_permittivity(race.eps_r, p0) * hz.free_h;
      c.g += hz.free_h / race.resistivity;
    }
  }
  const GapGeometry gap{
      std::max(c.film.central, race.sigma) + rest, race.rx, race.ry, a, b, race.r_wet};
  c.c_outer = strip_gap_capacitance(gap, race.eps_r, strip);
}

double idle_over_pit(const RaceInput &race, double gap, const PitStrip &strip)
{
  const GapGeometry g{std::max(gap, race.sigma), race.rx, race.ry, 0.0, 0.0, race.r_wet};
  return strip_gap_capacitance(g, race.eps_r, strip);
}

}  // namespace ohmdem::lubrication
