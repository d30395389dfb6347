// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance, the closed form of a bearing of model 3d: every conducting ball is
// one resistor between the races as in model 2d (resistance_path_closed_form.cpp), its spots as
// they are at this step, off the bearing plane and with the ellipse of their contact angle
// (lib/conduction/ball_between_races_3d.h). Adapter code (LIGGGHTS types).
#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/resistance_path_closed_form.h"
#include "atom.h"
#include "comm.h"
#include "conduction/ball_between_races_3d.h"
#include "conduction/contact_flows.h"

using namespace LAMMPS_NS;

// Ball i's resistances between the two races (its contact vectors from its centre in space).
ohmdem::BallResistances3d LAMMPS_NS::ball_between_3d(const ResistanceContext &context,
                                                     const FixBearingRace &a,
                                                     const FixBearingRace &b, const Atom &atom,
                                                     int i)
{
  const ohmdem::RaceContactView ca = a.contact_of(i), cb = b.contact_of(i);
  const double *x = atom.x[i];
  const double u[3] = {ca.point_x() - x[0], ca.point_y() - x[1], ca.point_z() - x[2]};
  double w[3] = {cb.point_x() - x[0], cb.point_y() - x[1], cb.point_z() - x[2]};
  if (&a == &b)
    for (int k = 0; k < 3; ++k) w[k] = -u[k];
  const ohmdem::AreaModel area = context.contacts->area_model();
  return ohmdem::ball_resistances_3d(context.model, context.gamma_type[atom.type[i]],
                                     atom.radius[i], context.gamma_type[a.race_type()],
                                     context.gamma_type[b.race_type()], a.ellipse_of(i, area),
                                     b.ellipse_of(i, area), u, w);
}

bool ClosedFormPath::evaluate_3d(double *phi, PathResult &result)
{
  const auto &races = context_.contacts->races();
  const FixBearingRace &race_hi = *races[context_.high.index];
  const FixBearingRace &race_lo = *races[context_.low.index];
  const bool races_conduct = context_.gamma_type[race_hi.race_type()] > 0.0 &&
                             context_.gamma_type[race_lo.race_type()] > 0.0;
  const int nlocal = atom->nlocal;
  balls_.resize(nlocal);
  g_local_.resize(nlocal);
  int nballs = 0, other = 0;
  for (int i = 0; i < nlocal; ++i) {
    phi[i] = 0.0;
    g_local_[i] = std::numeric_limits<double>::quiet_NaN();
    if (!(atom->mask[i] & context_.groupbit)) continue;
    for (const FixBearingRace *race : other_races_)
      if (race->contact_of(i).conducts()) ++other;
    const bool on_hi = race_hi.contact_of(i).conducts(), on_lo = race_lo.contact_of(i).conducts();
    if (!(context_.gamma_type[atom->type[i]] > 0.0) || !(on_hi || on_lo)) continue;
    const auto tag = static_cast<std::int64_t>(atom->tag[i]);
    if (!(on_hi && on_lo)) {
      phi[i] = on_hi ? 1.0 : 0.0;
      balls_[nballs++] = {tag, {0.0, 0.0, 1.0}};
      continue;
    }
    const double g =
        races_conduct ? 1.0 / ball_between_3d(context_, race_hi, race_lo, *atom, i).total() : 0.0;
    phi[i] = 0.5;
    g_local_[i] = g;
    balls_[nballs++] = {tag, {g, 1.0, 0.0}};
  }
  balls_.resize(nballs);
  int any_other = other;
  if (comm->nprocs > 1) MPI_Allreduce(&other, &any_other, 1, MPI_INT, MPI_SUM, world);
  if (any_other) return false;
  const auto sum = ohmdem::ordered_sum<3>(balls_gather_.gather(balls_, world));
  const int paths = static_cast<int>(sum[1]), dead = static_cast<int>(sum[2]);
  resistance_ = sum[0] > 0.0 ? 1.0 / sum[0] : std::numeric_limits<double>::infinity();
  result = PathResult{resistance_, 2 * paths + dead, 0, 0, 0.0};
  const double v_high = std::isfinite(resistance_) ? resistance_ * context_.current : 0.0;
  for (int i = 0; i < nlocal; ++i) phi[i] *= v_high;
  return true;
}

void ClosedFormPath::contact_flows_3d(std::vector<ohmdem::ContactFlow> &rows)
{
  const auto &races = context_.contacts->races();
  const FixBearingRace &race_hi = *races[context_.high.index];
  const FixBearingRace &race_lo = *races[context_.low.index];
  const double v = std::isfinite(resistance_) ? resistance_ * context_.current : 0.0;
  const bool constriction = context_.model.has_constriction();
  const ohmdem::AreaModel area = context_.contacts->area_model();
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context_.groupbit)) continue;
    const bool on_hi = race_hi.contact_of(i).conducts(), on_lo = race_lo.contact_of(i).conducts();
    if (!(context_.gamma_type[atom->type[i]] > 0.0) || !(on_hi || on_lo)) continue;
    const auto tag = static_cast<std::int64_t>(atom->tag[i]);
    if (!(on_hi && on_lo)) {
      const FixBearingRace &race = on_hi ? race_hi : race_lo;
      const ohmdem::ContactEllipse e = race.ellipse_of(i, area);
      const double r = context_.model.constriction_resistance(
          context_.gamma_type[atom->type[i]], context_.gamma_type[race.race_type()], e.a, e.b);
      rows.push_back(ohmdem::idle_race_flow(tag, on_hi ? 1 : -1, r, false));
      continue;
    }
    const ohmdem::BallResistances3d r = ball_between_3d(context_, race_hi, race_lo, *atom, i);
    ohmdem::ContactFlow two[2];
    ohmdem::ball_between_races_flows(tag, 1.0 / r.total(), v, constriction, r.hi, r.lo, two);
    rows.push_back(two[0]);
    rows.push_back(two[1]);
  }
}
