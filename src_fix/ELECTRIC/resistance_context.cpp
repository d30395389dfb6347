// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: what its evaluation paths share; see resistance_context.h.
#include "ELECTRIC/resistance_context.h"

#include <cstdint>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "atom.h"

using namespace LAMMPS_NS;

int ResistanceContext::race_electrode(int race) const
{
  if (high.kind == ElectrodeKind::Race && high.index == race) return 1;
  if (low.kind == ElectrodeKind::Race && low.index == race) return -1;
  return 0;
}

void ResistanceContext::gamma_race(std::vector<double> &out) const
{
  out.clear();
  for (const FixBearingRace *r : contacts->races()) out.push_back(gamma_type[r->race_type()]);
}

ohmdem::ParticleRecord ResistanceContext::particle(const Atom &atom, int i) const
{
  const int m = atom.mask[i];
  const auto member = (m & high.group_bit())  ? ohmdem::Membership::High
                      : (m & low.group_bit()) ? ohmdem::Membership::Low
                                              : ohmdem::Membership::None;
  return {static_cast<std::int64_t>(atom.tag[i]),
          {atom.x[i][0], atom.x[i][1], atom.x[i][2]},
          atom.radius[i],
          atom.type[i],
          member};
}
