// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance, the closed form of a bearing; see resistance_path_closed_form.h.
#include "ELECTRIC/resistance_path_closed_form.h"

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "comm.h"

using namespace LAMMPS_NS;

ClosedFormPath::ClosedFormPath(LAMMPS *lmp, const ResistanceContext &context)
    : Pointers(lmp), context_(context)
{
}

void ClosedFormPath::set_geometry()
{
  ContactSet &contacts = *context_.contacts;
  const auto &races = contacts.races();
  const int high = context_.high.index, low = context_.low.index;
  const std::vector<double> &gamma_type = context_.gamma_type;
  between_races_ = ohmdem::BallBetweenRaces(
      context_.model, contacts.race_geometry(high), contacts.race_geometry(low),
      gamma_type[races[high]->race_type()], gamma_type[races[low]->race_type()], gamma_type);
  other_races_.clear();
  for (int k = 0; k < static_cast<int>(races.size()); ++k)
    if (k != high && k != low) other_races_.push_back(races[k]);
  geometry_ready_ = true;
}

bool ClosedFormPath::evaluate(double *phi, PathResult &result)
{
  if (!geometry_ready_) set_geometry();
  if (context_.contacts->races()[context_.high.index]->three_d()) return evaluate_3d(phi, result);
  const ohmdem::BallBetweenRaces::Kernel model = between_races_.kernel();
  const double inf = std::numeric_limits<double>::infinity();

  // Local copies of LIGGGHTS' arrays: the loop stays in registers (this runs every step).
  const auto &races = context_.contacts->races();
  const int nlocal = atom->nlocal;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const tagint *const tag = atom->tag;
  const double *const *const x = atom->x;
  const double *const radius = atom->radius;
  const FixBearingRace &race_hi = *races[context_.high.index];
  const FixBearingRace &race_lo = *races[context_.low.index];
  const double *const gamma_type = context_.gamma_type.data();
  const int bit = context_.groupbit;

  balls_.resize(nlocal);
  ohmdem::TaggedValues<3> *out = balls_.data();
  g_local_.resize(nlocal);
  double *const g_local = g_local_.data();
  int nballs = 0, other = 0;
  for (int i = 0; i < nlocal; ++i) {
    phi[i] = 0.0;  // potential / V_high, scaled once R is known
    g_local[i] = std::numeric_limits<double>::quiet_NaN();
    if (!(mask[i] & bit)) continue;
    for (const FixBearingRace *race : other_races_)
      if (race->contact_of(i).conducts()) ++other;
    const ohmdem::RaceContactView ch = race_hi.contact_of(i), cl = race_lo.contact_of(i);
    const bool on_hi = ch.conducts(), on_lo = cl.conducts();
    const double gamma = gamma_type[type[i]];
    if (!(gamma > 0.0) || !(on_hi || on_lo)) continue;
    if (!(on_hi && on_lo)) {
      // A dead end: no current; its contact node sits at that electrode's potential.
      phi[i] = on_hi ? 1.0 : 0.0;
      out[nballs++] = {static_cast<std::int64_t>(tag[i]), {0.0, 0.0, 1.0}};
      continue;
    }
    const double u[3] = {ch.point_x() - x[i][0], ch.point_y() - x[i][1], 0.0};
    const double w[3] = {cl.point_x() - x[i][0], cl.point_y() - x[i][1], 0.0};
    const double conductance = model.conductance(type[i], gamma, radius[i], ch.fn(), cl.fn(), u, w);
    phi[i] = 0.5;
    g_local[i] = conductance;
    out[nballs++] = {static_cast<std::int64_t>(tag[i]), {conductance, 1.0, 0.0}};
  }
  balls_.resize(nballs);
  int any_other = other;
  if (comm->nprocs > 1) MPI_Allreduce(&other, &any_other, 1, MPI_INT, MPI_SUM, world);
  if (any_other) return false;  // a third conducting race: the general network handles it

  // Conductances added in tag order: the same R with any number of processes.
  const auto sum = ohmdem::ordered_sum<3>(balls_gather_.gather(balls_, world));
  const double conductance = sum[0];
  const int paths = static_cast<int>(sum[1]), dead = static_cast<int>(sum[2]);
  resistance_ = conductance > 0.0 ? 1.0 / conductance : inf;
  result = PathResult{resistance_, 2 * paths + dead, 0, 0, 0.0};
  // Per-atom potential: mean of the contact-node potentials (the electrodes' own).
  const double v_high = std::isfinite(resistance_) ? resistance_ * context_.current : 0.0;
  for (int i = 0; i < nlocal; ++i) phi[i] *= v_high;
  return true;
}

void ClosedFormPath::contact_flows(std::vector<ohmdem::ContactFlow> &rows)
{
  if (context_.contacts->races()[context_.high.index]->three_d()) {
    contact_flows_3d(rows);
    return;
  }
  const auto &races = context_.contacts->races();
  const FixBearingRace &race_hi = *races[context_.high.index];
  const FixBearingRace &race_lo = *races[context_.low.index];
  const double v = std::isfinite(resistance_) ? resistance_ * context_.current : 0.0;
  const bool constriction = context_.model.has_constriction();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context_.groupbit)) continue;
    const double gamma = context_.gamma_type[atom->type[i]];
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
