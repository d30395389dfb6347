// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute contact/area. The contacts and their areas come from
   ELECTRIC/contact_set.*; this file parses and fills the local array.
------------------------------------------------------------------------- */

#include "ELECTRIC/compute_contact_area.h"

#include <string>
#include <vector>

#include "ELECTRIC/contact_set.h"
#include "common/constants.h"
#include "memory.h"
#include "support/args.h"
#include "support/require_si.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kCols = 7;  // id1, id2, race, fn, a, b, S
}

ComputeContactArea::ComputeContactArea(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg)
{
  ohmdem::StyleArgs a(error, "compute contact/area", narg, arg, 3);
  bool exact = false, pair = true;
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "area") {
      const std::string m = a.word(kw, "greenwood or exact");
      if (m == "greenwood")
        exact = false;
      else if (m == "exact")
        exact = true;
      else
        a.fail(kw, "greenwood or exact", m.c_str());
    } else if (kw == "pair") {
      pair = a.yes_no(kw);
    } else {
      a.unknown(kw.c_str(), "area pair");
    }
  }
  local_flag = 1;
  size_local_cols = kCols;
  size_local_rows = 0;
  array_local = nullptr;
  contacts_ = std::make_unique<ContactSet>(
      lmp, id, exact ? ohmdem::AreaModel::Exact : ohmdem::AreaModel::Greenwood, pair);
}

ComputeContactArea::~ComputeContactArea()
{
  memory->destroy(array_local);
}

void ComputeContactArea::init()
{
  ohmdem::require_si_units(lmp, "compute contact/area");
  contacts_->init(groupbit);
}

void ComputeContactArea::compute_local()
{
  invoked_local = update->ntimestep;
  std::vector<ohmdem::ContactRecord> found;
  contacts_->collect(found);
  const int n = static_cast<int>(found.size());
  if (n > nmax_) {
    nmax_ = n;
    memory->destroy(array_local);
    memory->create(array_local, nmax_, kCols, "contact/area:array_local");
  }
  size_local_rows = n;
  for (int r = 0; r < n; ++r) {
    const auto &c = found[r];
    double *row = array_local[r];
    row[0] = static_cast<double>(c.tag);
    row[1] = static_cast<double>(c.other);
    row[2] = c.race + 1;  // 1-based race number, 0 for a particle–particle contact
    row[3] = c.fn;
    row[4] = c.a;
    row[5] = c.b;
    row[6] = ohmdem::kPi * c.a * c.b;  // as ContactEllipse::area (contact/hertz_contact.cpp)
  }
}

double ComputeContactArea::memory_usage()
{
  return static_cast<double>(nmax_) * kCols * sizeof(double);
}
