// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricated contacts as a VTK companion file; see lubricated_vtk.h.
#include "ELECTRIC/lubricated_vtk.h"

#include <cmath>
#include <cstddef>
#include <string>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/lubricated_bearing.h"
#include "ELECTRIC/resistance_context.h"
#include "atom.h"
#include "lubrication/contact_admittance.h"
#include "writers/contact_points_vtk.h"

using namespace LAMMPS_NS;

VtkPartFn LubricatedVtk::gather(const LubricatedBearing &bearing, const ResistanceContext &context,
                                std::complex<double> v_high)
{
  const std::vector<LubricatedContact> &records = bearing.contacts();
  const auto &races = context.contacts->races();
  const FixBearingRace *race[2] = {races[context.high.index], races[context.low.index]};
  local_.clear();
  // The records follow the local atoms in order, two per ball: find each ball's atom.
  std::size_t k = 0;
  for (int i = 0; i < atom->nlocal && k < records.size(); ++i) {
    if (static_cast<std::int64_t>(atom->tag[i]) != records[k].tag) continue;
    for (; k < records.size() && records[k].tag == static_cast<std::int64_t>(atom->tag[i]); ++k) {
      const LubricatedContact &c = records[k];
      // The contact point: the ball's surface on the line through the race's centre.
      double cx, cy;
      race[c.side]->centre(cx, cy);
      const double *x = atom->x[i];
      const double dx = x[0] - cx, dy = x[1] - cy, d = std::hypot(dx, dy);
      const double s = (race[c.side]->is_inner() ? -atom->radius[i] : atom->radius[i]) / d;
      local_.push_back(
          {c.tag,
           {static_cast<double>(c.side), c.loaded ? 1.0 : 0.0, x[0] + s * dx, x[1] + s * dy, x[2],
            c.h_central, c.h_min, c.lambda, c.c, c.g, c.y.real(), c.y.imag()}});
    }
  }
  all_ = ohmdem::gather_by_tag(local_, world);  // by tag, then side
  return [this, v_high](std::ostream &os) { write(os, v_high); };
}

// A ball's two contacts in series carry the ball's current y_series v_high, into the ball at
// the high race and out at the low one (as the local array's columns).
void LubricatedVtk::write(std::ostream &os, std::complex<double> v_high) const
{
  std::vector<ohmdem::ContactPoint> points;
  points.reserve(all_.size());
  for (std::size_t k = 0; k < all_.size(); ++k) {
    const auto &r = all_[k];
    const std::size_t other = k + 1 < all_.size() && all_[k + 1].tag == r.tag ? k + 1
                              : k > 0 && all_[k - 1].tag == r.tag             ? k - 1
                                                                              : k;
    const std::complex<double> y(r.v[10], r.v[11]);
    const std::complex<double> ball =
        other == k ? std::complex<double>(0.0, 0.0)
                   : ohmdem::lubrication::series(y, {all_[other].v[10], all_[other].v[11]});
    const std::complex<double> into = (r.v[0] == 0.0 ? 1.0 : -1.0) * ball * v_high;
    ohmdem::ContactPoint p;
    p.ball = r.tag;
    p.race = static_cast<int>(r.v[0]);
    for (int a = 0; a < 3; ++a) p.at[a] = r.v[2 + a];
    p.values = {r.v[5], r.v[6], r.v[7], r.v[8], r.v[9], std::abs(into), std::arg(into), r.v[1]};
    points.push_back(std::move(p));
  }
  ohmdem::write_contact_points_vtk(
      os, points,
      {"h_central", "h_min", "lambda", "C", "G", "current_abs", "current_phase", "loaded"},
      "ohmdem lubricated contacts");
}
