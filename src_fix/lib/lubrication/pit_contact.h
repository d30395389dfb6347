// SPDX-License-Identifier: GPL-2.0-or-later
// A loaded contact of a race whose wetted circle meets a race pit (a strip across the raceway,
// pit_gap.h): the Hertz zone's film and metal and the gap around it over the strip instead of
// a recess added over the whole wetted circle. Plain C++; doc/methods/lubricated_contact.md, "Defects:
// a pit under the film".
#ifndef OHMDEM_LUBRICATION_PIT_CONTACT_H
#define OHMDEM_LUBRICATION_PIT_CONTACT_H

#include "lubrication/contact_admittance.h"
#include "lubrication/pit_gap.h"
#include "lubrication/race_admittance.h"

namespace ohmdem::lubrication {

// c: RaceAdmittance::contact's result for this contact (load fn > 0) with the recess `rest`
// of the other defects under it (a ball's pit, added over the whole circle; 0 without). Its
// film, lambda and g_dry stay; over the strip (in the contact's rolling coordinate):
// * the Hertz zone (when the strip meets its span |x| < b): the film is h_c + rest + r(x) and
//   the metallic fraction erfc((h_min + rest + r(x)) / (sigma sqrt 2)) at each x; the metal
//   conducts as the area mean of that fraction times g_dry (0 in a defect zone), the oil over
//   the rest: C = eps0 eps_mean int (1 - f)/h dA, its leakage int (1 - f)/h dA / rho;
//   `gap` = h_min + rest + the smallest r(x) over the ellipse;
// * the gap around it: strip_gap_capacitance with h0 = max(h_c, sigma) + rest.
void contact_over_pit(const RaceInput &race, double fn, double rest, const PitStrip &strip,
                      ContactAdmittance &c);

// A ball that does not press the race, over or near its pit: idle_gap_capacitance's gap
// (nothing excluded, h0 = max(gap, sigma); `gap` without the pit's recess) with the strip.
double idle_over_pit(const RaceInput &race, double gap, const PitStrip &strip);

}  // namespace ohmdem::lubrication

#endif
