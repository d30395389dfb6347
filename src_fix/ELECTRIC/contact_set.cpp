// SPDX-License-Identifier: GPL-2.0-or-later
#include "ELECTRIC/contact_set.h"

#include <cmath>
#include <cstdint>

#include "BEARING/fix_bearing_race.h"
#include "atom.h"
#include "compute_pair_gran_local.h"
#include "contact/race_contact.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair.h"
#include "support/material_table.h"

using namespace LAMMPS_NS;

ContactSet::ContactSet(LAMMPS *lmp, const std::string &owner_id, ohmdem::AreaModel model,
                       bool use_pair)
    : Pointers(lmp), owner_id_(owner_id), model_(model), want_pair_(use_pair)
{
}

// The internal pair/gran/local compute is left to LIGGGHTS (deleted by `clear`): deleting it
// here could run while Modify itself is being destroyed.
ContactSet::~ContactSet() = default;

void ContactSet::init(int groupbit)
{
  groupbit_ = groupbit;
  races_.clear();
  race_hertz_.clear();
  for (int k = 0; k < modify->nfix; ++k) {
    auto *race = dynamic_cast<FixBearingRace *>(modify->fix[k]);
    if (!race) continue;
    races_.push_back(race);
  }
  // Contact geometry of each race in the chosen area mode; the race fix itself always uses
  // the exact Hertz force law. Built lazily: the race model exists after the race's setup.
  if (want_pair_ && !pgl_) {
    if (!force->pair || !force->pair_match("gran", 0))
      error->all(FLERR, ("compute " + owner_id_ +
                         ": keyword 'pair yes' needs a granular pair style (pair_style gran ...)")
                            .c_str());
    // LIGGGHTS' granular pair style serves a single pair/gran/local compute: share it.
    for (int k = 0; k < modify->ncompute && !pgl_; ++k)
      if (std::string(modify->compute[k]->style) == "pair/gran/local")
        pgl_ = static_cast<ComputePairGranLocal *>(modify->compute[k]);
    if (!pgl_) {
      const char *arg[] = {"ohmdem_pair_contacts", "all", "pair/gran/local", "pos", "id",
                           "force_normal"};
      modify->add_compute(6, const_cast<char **>(arg));
      pgl_ = static_cast<ComputePairGranLocal *>(
          modify->compute[modify->find_compute("ohmdem_pair_contacts")]);
    }
    if (pgl_->offset_id1() < 0 || pgl_->offset_fn() < 0)
      error->all(FLERR, ("compute " + owner_id_ + ": the compute pair/gran/local of this run ('" +
                         std::string(pgl_->id) +
                         "') must include the keywords id and force_normal: LIGGGHTS allows "
                         "only one, and ohmdem reads particle contacts from it")
                            .c_str());
  }
}

void ContactSet::collect(std::vector<ohmdem::ContactRecord> &out)
{
  out.clear();
  collect_races(out);
  if (pgl_) collect_pairs(out);
}

const ohmdem::HertzContact &ContactSet::race_geometry(int k)
{
  if (race_hertz_.size() != races_.size()) {
    race_hertz_.clear();
    for (auto *race : races_) {
      const auto &h = race->contact_model().hertz;
      race_hertz_.emplace_back(h.sums(), h.E_eff(), model_);
    }
  }
  return race_hertz_[k];
}

void ContactSet::collect_races(std::vector<ohmdem::ContactRecord> &out)
{
  const int nlocal = atom->nlocal;
  for (std::size_t k = 0; k < races_.size(); ++k) {
    for (int i = 0; i < nlocal; ++i) {
      if (!(atom->mask[i] & groupbit_)) continue;
      const ohmdem::RaceContactView c = races_[k]->contact_of(i);
      if (!c.conducts()) continue;  // no force, or in a defect zone: no current
      ohmdem::ContactRecord ct;
      ct.tag = static_cast<std::int64_t>(atom->tag[i]);
      ct.race = static_cast<int>(k);
      ct.fn = c.fn();
      ct.point[0] = c.point_x();
      ct.point[1] = c.point_y();
      // Model 3d: the point off the plane, the ellipse of its contact angle.
      const bool three_d = races_[k]->three_d();
      ct.point[2] = three_d ? c.point_z() : atom->x[i][2];
      const ohmdem::ContactEllipse e = three_d ? races_[k]->ellipse_of(i, model_)
                                               : race_geometry(static_cast<int>(k)).ellipse(ct.fn);
      ct.a = e.a;
      ct.b = e.b;
      out.push_back(ct);
    }
  }
}

void ContactSet::collect_pairs(std::vector<ohmdem::ContactRecord> &out)
{
  pgl_->compute_local();
  double **data = pgl_->get_data();
  const int n = pgl_->get_ncount();
  const int oid = pgl_->offset_id1(), ofn = pgl_->offset_fn();
  const ohmdem::MaterialTable mat(lmp, "contact set", false, false);
  for (int r = 0; r < n; ++r) {
    const double *row = data[r];
    const auto t1 = static_cast<tagint>(row[oid]), t2 = static_cast<tagint>(row[oid + 1]);
    const int i = atom->map(t1), j = atom->map(t2);
    if (i < 0 || j < 0) continue;
    if (!(atom->mask[i] & groupbit_) || !(atom->mask[j] & groupbit_)) continue;
    double n12[3], d = 0.0;
    for (int k = 0; k < 3; ++k) {
      n12[k] = atom->x[j][k] - atom->x[i][k];
      d += n12[k] * n12[k];
    }
    d = std::sqrt(d);
    if (!(d > 0.0)) continue;
    for (double &v : n12) v /= d;
    // pair/gran/local stores the normal force on particle 1: compressive when it points
    // from 2 to 1.
    const double fn = -(row[ofn] * n12[0] + row[ofn + 1] * n12[1] + row[ofn + 2] * n12[2]);
    if (!(fn > 0.0)) continue;
    const double ri = atom->radius[i], rj = atom->radius[j];
    const double delta = ri + rj - d;
    ohmdem::ContactRecord ct;
    ct.tag = static_cast<std::int64_t>(t1);
    ct.other = static_cast<std::int64_t>(t2);
    ct.fn = fn;
    for (int k = 0; k < 3; ++k) ct.point[k] = atom->x[i][k] + (ri - 0.5 * delta) * n12[k];
    const ohmdem::HertzContact h(ohmdem::sphere_sphere(ri, rj),
                                 mat.E_eff(atom->type[i], atom->type[j]), model_);
    const ohmdem::ContactEllipse e = h.ellipse(fn);
    ct.a = e.a;
    ct.b = e.b;
    out.push_back(ct);
  }
}
