// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: its local array, one row per conducting contact whose atom
// this process owns (electric/contact_flows.h gives the rows; columns in its ContactFlow),
// plus the ball–race contacts in a defect zone (masked). Filled only on the steps a dump or
// compute asks for it; compute network/contacts reads the same array. Adapter code.
#ifndef OHMDEM_STYLE_CONTACT_FLOW_ARRAY_H
#define OHMDEM_STYLE_CONTACT_FLOW_ARRAY_H

#include <vector>

#include "conduction/contact_flows.h"
#include "pointers.h"

namespace LAMMPS_NS {

class ResistancePath;
struct ResistanceContext;

class ContactFlowArray : protected Pointers {
 public:
  explicit ContactFlowArray(LAMMPS *lmp);
  ~ContactFlowArray();
  // The rows of `path`'s last evaluation and the masked contacts, in a fixed order; returns
  // their number. rows() stays valid until the next fill.
  int fill(ResistancePath &path, const ResistanceContext &context);
  double **rows() const { return array_; }
  double memory_usage() const;

 private:
  void masked_flows(const ResistanceContext &context);

  std::vector<ohmdem::ContactFlow> flows_;  // kept for reuse
  double **array_ = nullptr;
  int capacity_ = 0;
};

}  // namespace LAMMPS_NS

#endif
