// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/contacts: the per-contact local array of a compute
   network/resistance, alone. LIGGGHTS' compute reduce reads a compute's per-atom output
   whenever it has one, so it cannot reach network/resistance's local array; through this
   compute it can (dump local reads either).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

// clang-format off
ComputeStyle(network/contacts,ComputeNetworkContacts)
// clang-format on

#else

#ifndef LMP_COMPUTE_NETWORK_CONTACTS_H
#define LMP_COMPUTE_NETWORK_CONTACTS_H

#include <string>

#include "compute.h"

namespace LAMMPS_NS {

class ComputeNetworkResistance;

class ComputeNetworkContacts : public Compute {
 public:
  ComputeNetworkContacts(class LAMMPS *, int &iarg, int, char **);
  void init() override;
  void compute_local() override;

 private:
  std::string source_id_;
  ComputeNetworkResistance *source_ = nullptr;
};

}  // namespace LAMMPS_NS

#endif
#endif
