// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: its local array; see contact_flow_array.h.
#include "ELECTRIC/contact_flow_array.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/resistance_context.h"
#include "ELECTRIC/resistance_path.h"
#include "atom.h"
#include "memory.h"

using namespace LAMMPS_NS;

ContactFlowArray::ContactFlowArray(LAMMPS *lmp) : Pointers(lmp) {}

ContactFlowArray::~ContactFlowArray()
{
  memory->destroy(array_);
}

// Ball–race contacts in a defect zone: pressed, but carrying no current (masked = 1).
void ContactFlowArray::masked_flows(const ResistanceContext &context)
{
  const auto &races = context.contacts->races();
  for (int k = 0; k < static_cast<int>(races.size()); ++k)
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(atom->mask[i] & context.groupbit) || !(context.gamma_type[atom->type[i]] > 0.0))
        continue;
      const ohmdem::RaceContactView c = races[k]->contact_of(i);
      if (c.fn() > 0.0 && c.in_defect())
        flows_.push_back(ohmdem::idle_race_flow(static_cast<std::int64_t>(atom->tag[i]),
                                                context.race_electrode(k), 0.0, true));
    }
}

int ContactFlowArray::fill(ResistancePath &path, const ResistanceContext &context)
{
  flows_.clear();
  path.contact_flows(flows_);
  masked_flows(context);
  // A fixed order, the same with any number of processes: by atom, then partner, the high
  // electrode before the low one, then conductance and current.
  std::sort(flows_.begin(), flows_.end(), [](const auto &a, const auto &b) {
    if (a.atom != b.atom) return a.atom < b.atom;
    if (a.partner != b.partner) return a.partner < b.partner;
    if (a.electrode != b.electrode) return a.electrode > b.electrode;
    if (a.conductance != b.conductance) return a.conductance < b.conductance;
    return a.current < b.current;
  });
  const int n = static_cast<int>(flows_.size());
  if (n > capacity_) {
    capacity_ = n;
    memory->destroy(array_);
    memory->create(array_, capacity_, ohmdem::ContactFlow::kColumns,
                   "network/resistance:array_local");
  }
  for (int r = 0; r < n; ++r) {
    const auto &f = flows_[r];
    double *row = array_[r];
    row[ohmdem::ContactFlow::kAtom] = static_cast<double>(f.atom);
    row[ohmdem::ContactFlow::kPartner] = static_cast<double>(f.partner);
    row[ohmdem::ContactFlow::kConductance] = f.conductance;
    row[ohmdem::ContactFlow::kCurrent] = f.current;
    row[ohmdem::ContactFlow::kDrop] = f.drop;
    row[ohmdem::ContactFlow::kMasked] = f.masked;
    row[ohmdem::ContactFlow::kElectrode] = f.electrode;
  }
  return n;
}

double ContactFlowArray::memory_usage() const
{
  return static_cast<double>(capacity_) * ohmdem::ContactFlow::kColumns * sizeof(double);
}
