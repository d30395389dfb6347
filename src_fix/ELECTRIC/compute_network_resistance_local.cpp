// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: the local array, one row per conducting contact whose atom
// this process owns (conduction/contact_flows.h gives the rows; columns in its ContactFlow).
// Computed only on the steps a dump or compute asks for it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/compute_network_resistance.h"
#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "conduction/contact_flows.h"
#include "error.h"
#include "memory.h"
#include "network/conduction_network.h"
#include "update.h"

using namespace LAMMPS_NS;

int ComputeNetworkResistance::race_electrode(int race) const
{
  if (high_.kind == ElectrodeKind::Race && high_.index == race) return 1;
  if (low_.kind == ElectrodeKind::Race && low_.index == race) return -1;
  return 0;
}

// The closed form: each ball joining both races is one resistor carrying g_ball * V.
void ComputeNetworkResistance::closed_form_flows(std::vector<ohmdem::ContactFlow> &rows)
{
  const auto &races = contacts_->races();
  const FixBearingRace &race_hi = *races[high_.index];
  const FixBearingRace &race_lo = *races[low_.index];
  const double v = std::isfinite(result_[0]) ? result_[0] * current_ : 0.0;
  const bool constriction = model_.has_constriction();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double gamma = gamma_type_[atom->type[i]];
    const ohmdem::RaceContactView ch = race_hi.contact_of(i), cl = race_lo.contact_of(i);
    const bool on_hi = ch.conducts(), on_lo = cl.conducts();
    if (!(gamma > 0.0) || !(on_hi || on_lo)) continue;
    const auto tag = static_cast<std::int64_t>(atom->tag[i]);
    const int t = atom->type[i];
    if (!(on_hi && on_lo)) {  // a dead end: no current
      const double fn = on_hi ? ch.fn() : cl.fn();
      double r_hi = 0, r_lo = 0;
      between_races_.constrictions(t, fn, fn, r_hi, r_lo);
      rows.push_back(ohmdem::idle_race_flow(tag, on_hi ? 1 : -1, on_hi ? r_hi : r_lo, false));
      continue;
    }
    // The same conductance as the evaluation of this step (same inputs, same code).
    const double *x = atom->x[i];
    const double u[3] = {ch.point_x() - x[0], ch.point_y() - x[1], 0.0};
    const double w[3] = {cl.point_x() - x[0], cl.point_y() - x[1], 0.0};
    const double g = between_races_.conductance(t, gamma, atom->radius[i], ch.fn(), cl.fn(), u, w);
    double r_hi = 0, r_lo = 0;
    between_races_.constrictions(t, ch.fn(), cl.fn(), r_hi, r_lo);
    ohmdem::ContactFlow two[2];
    ohmdem::ball_between_races_flows(tag, g, v, constriction, r_hi, r_lo, two);
    rows.push_back(two[0]);
    rows.push_back(two[1]);
  }
}

// The general network: rows of the whole (gathered) network, kept for the atoms owned here.
void ComputeNetworkResistance::network_flows(std::vector<ohmdem::ContactFlow> &rows)
{
  const ohmdem::NetworkScene scene{&particles_, &contact_records_, &gamma_type_, &gamma_race_,
                                   false};
  ohmdem::network_contact_flows(model_, scene, built_, *network_, all_flows_);
  std::vector<std::int64_t> mine;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) mine.push_back(static_cast<std::int64_t>(atom->tag[i]));
  std::sort(mine.begin(), mine.end());
  for (const auto &row : all_flows_)
    if (std::binary_search(mine.begin(), mine.end(), row.atom)) rows.push_back(row);
}

// Ball–race contacts in a defect zone: pressed, but carrying no current (masked = 1).
void ComputeNetworkResistance::masked_flows(std::vector<ohmdem::ContactFlow> &rows)
{
  const auto &races = contacts_->races();
  for (int k = 0; k < static_cast<int>(races.size()); ++k)
    for (int i = 0; i < atom->nlocal; ++i) {
      if (!(atom->mask[i] & groupbit) || !(gamma_type_[atom->type[i]] > 0.0)) continue;
      const ohmdem::RaceContactView c = races[k]->contact_of(i);
      if (c.fn() > 0.0 && c.in_defect())
        rows.push_back(ohmdem::idle_race_flow(static_cast<std::int64_t>(atom->tag[i]),
                                              race_electrode(k), 0.0, true));
    }
}

void ComputeNetworkResistance::compute_local()
{
  invoked_local = update->ntimestep;
  evaluate();
  flows_.clear();
  if (closed_form_used_) {
    closed_form_flows(flows_);
  } else if (distributed_used_) {
    // The rows need every node potential: the distributed solve keeps each on its owner.
    error->all(FLERR,
               "compute network/resistance: the per-contact local array needs the gathered "
               "network solve, not solver distributed (solver auto goes distributed from 20000 "
               "particles on more than one process): give solver direct, cg or amg");
  } else {
    network_flows(flows_);
  }
  masked_flows(flows_);
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
  if (n > local_capacity_) {
    local_capacity_ = n;
    memory->destroy(array_local);
    memory->create(array_local, local_capacity_, ohmdem::ContactFlow::kColumns,
                   "network/resistance:array_local");
  }
  for (int r = 0; r < n; ++r) {
    const auto &f = flows_[r];
    double *row = array_local[r];
    row[ohmdem::ContactFlow::kAtom] = static_cast<double>(f.atom);
    row[ohmdem::ContactFlow::kPartner] = static_cast<double>(f.partner);
    row[ohmdem::ContactFlow::kConductance] = f.conductance;
    row[ohmdem::ContactFlow::kCurrent] = f.current;
    row[ohmdem::ContactFlow::kDrop] = f.drop;
    row[ohmdem::ContactFlow::kMasked] = f.masked;
    row[ohmdem::ContactFlow::kElectrode] = f.electrode;
  }
  size_local_rows = n;
}
