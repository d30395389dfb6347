// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/contacts: forwards the local array of a compute network/resistance
// (doc/compute_network_resistance.md, "Output info"); see compute_network_contacts.h.
#include "ELECTRIC/compute_network_contacts.h"

#include <string>

#include "ELECTRIC/compute_network_resistance.h"
#include "conduction/contact_flows.h"
#include "error.h"
#include "modify.h"
#include "support/args.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeNetworkContacts::ComputeNetworkContacts(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg)
{
  ohmdem::StyleArgs a(error, "compute network/contacts", narg, arg, 3);
  source_id_ = a.word("compute", "the ID of a compute network/resistance");
  if (!a.done()) a.fail("compute", "one argument, the ID of a compute network/resistance", arg[4]);
  local_flag = 1;
  size_local_cols = ohmdem::ContactFlow::kColumns;
  size_local_rows = 0;
}

void ComputeNetworkContacts::init()
{
  const int k = modify->find_compute(source_id_.c_str());
  source_ = k < 0 ? nullptr : dynamic_cast<ComputeNetworkResistance *>(modify->compute[k]);
  if (!source_)
    error->all(FLERR, ("compute network/contacts: no compute network/resistance with ID '" +
                       source_id_ + "'")
                          .c_str());
}

void ComputeNetworkContacts::compute_local()
{
  invoked_local = update->ntimestep;
  if (source_->invoked_local != update->ntimestep) source_->compute_local();
  size_local_rows = source_->size_local_rows;
  array_local = source_->array_local;  // owned by the source
}
