// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: its local array; see contact_flow_array.h.
#include "ELECTRIC/contact_flow_array.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/lubricated_bearing.h"
#include "ELECTRIC/resistance_context.h"
#include "ELECTRIC/resistance_path.h"
#include "atom.h"
#include "lubrication/contact_admittance.h"
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
  return fill(path, context, nullptr, {0.0, 0.0});
}

int ContactFlowArray::fill(ResistancePath &path, const ResistanceContext &context,
                           const std::vector<LubricatedContact> *records,
                           std::complex<double> v_high)
{
  flows_.clear();
  path.contact_flows(flows_);
  masked_flows(context);
  // (tag, electrode) of each record: the high race +1, the low -1.
  auto electrode_of = [](const LubricatedContact &c) { return c.side == 0 ? 1 : -1; };
  if (records) {
    std::set<std::pair<std::int64_t, int>> have;
    for (const auto &f : flows_)
      if (f.partner == 0) have.insert({f.atom, f.electrode});
    for (const LubricatedContact &c : *records)
      if (!have.count({c.tag, electrode_of(c)}))
        flows_.push_back(ohmdem::idle_race_flow(c.tag, electrode_of(c), 0.0, false));
  }
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
  const int columns = ohmdem::ContactFlow::kColumns + (records ? kLubricatedColumns : 0);
  if (n > capacity_ || columns != columns_) {
    capacity_ = std::max(n, capacity_);
    columns_ = columns;
    memory->destroy(array_);
    memory->create(array_, capacity_, columns_, "network/resistance:array_local");
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
    std::fill(row + ohmdem::ContactFlow::kColumns, row + columns_, 0.0);
  }
  if (records) lubricated_columns(*records, v_high, n);
  return n;
}

// The records come two per ball (high race, low race): the ball's current phasor is
// v_high y_high y_low / (y_high + y_low), into the ball at the high race, out at the low one.
void ContactFlowArray::lubricated_columns(const std::vector<LubricatedContact> &records,
                                          std::complex<double> v_high, int n)
{
  std::map<std::pair<std::int64_t, int>, int> row_of;
  for (int r = 0; r < n; ++r)
    if (flows_[r].partner == 0) row_of[{flows_[r].atom, flows_[r].electrode}] = r;
  for (std::size_t k = 0; k + 1 < records.size(); k += 2) {
    const LubricatedContact *ball[2] = {&records[k], &records[k + 1]};
    const std::complex<double> y = ohmdem::lubrication::series(ball[0]->y, ball[1]->y);
    const std::complex<double> current = y * v_high;
    for (int s = 0; s < 2; ++s) {
      const LubricatedContact &c = *ball[s];
      const auto it = row_of.find({c.tag, c.side == 0 ? 1 : -1});
      if (it == row_of.end()) continue;
      double *row = array_[it->second] + ohmdem::ContactFlow::kColumns;
      const std::complex<double> into = c.side == 0 ? current : -current;
      const double values[kLubricatedColumns] = {c.h_central, c.h_min,     c.lambda,   c.c,
                                                 c.g,         into.real(), into.imag()};
      std::copy(values, values + kLubricatedColumns, row);
    }
  }
}

double ContactFlowArray::memory_usage() const
{
  return static_cast<double>(capacity_) * columns_ * sizeof(double);
}
