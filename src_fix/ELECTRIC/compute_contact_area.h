// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute contact/area: one row per conducting contact with its
   rigid-Hertz contact ellipse (paper eqs. 2-5), for dump local.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

// clang-format off
ComputeStyle(contact/area,ComputeContactArea)
// clang-format on

#else

#ifndef LMP_COMPUTE_CONTACT_AREA_H
#define LMP_COMPUTE_CONTACT_AREA_H

#include <memory>

#include "compute.h"

namespace LAMMPS_NS {

class ContactSet;

class ComputeContactArea : public Compute {
 public:
  ComputeContactArea(class LAMMPS *, int &iarg, int, char **);
  ~ComputeContactArea() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  std::unique_ptr<ContactSet> contacts_;
  int nmax_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
