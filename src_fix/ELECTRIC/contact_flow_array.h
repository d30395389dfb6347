// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: its local array, one row per conducting contact whose atom
// this process owns (electric/contact_flows.h gives the rows; columns in its ContactFlow),
// plus the ball–race contacts in a defect zone (masked). Filled only on the steps a dump or
// compute asks for it; compute network/contacts reads the same array. Adapter code.
#ifndef OHMDEM_STYLE_CONTACT_FLOW_ARRAY_H
#define OHMDEM_STYLE_CONTACT_FLOW_ARRAY_H

#include <complex>
#include <vector>

#include "conduction/contact_flows.h"
#include "pointers.h"

namespace LAMMPS_NS {

class ResistancePath;
struct ResistanceContext;
struct LubricatedContact;

// With a lubricant, columns after ContactFlow's: the film (central, minimum; for a ball not
// pressing the race, the gap to it), lambda, the capacitance and conductance of Y = G + j
// omega C, and the contact's current phasor (real, imaginary; from the partner into the atom,
// the injected current I being real).
enum LubricatedColumn {
  kFilmCentral,
  kFilmMinimum,
  kLambda,
  kCapacitance,
  kAcConductance,
  kCurrentRe,
  kCurrentIm,
  kLubricatedColumns
};

class ContactFlowArray : protected Pointers {
 public:
  explicit ContactFlowArray(LAMMPS *lmp);
  ~ContactFlowArray();
  // The rows of `path`'s last evaluation and the masked contacts, in a fixed order; returns
  // their number. rows() stays valid until the next fill.
  int fill(ResistancePath &path, const ResistanceContext &context);
  // With a lubricant: the rows of every ball-race contact of the two races (also those that
  // carry no DC current: their AC current flows through the film or the gap), the
  // lubricated columns from this process's records; v_high: the high electrode's phasor.
  int fill(ResistancePath &path, const ResistanceContext &context,
           const std::vector<LubricatedContact> *records, std::complex<double> v_high);
  double **rows() const { return array_; }
  double memory_usage() const;

 private:
  void masked_flows(const ResistanceContext &context);
  void lubricated_columns(const std::vector<LubricatedContact> &records,
                          std::complex<double> v_high, int n);

  std::vector<ohmdem::ContactFlow> flows_;  // kept for reuse
  double **array_ = nullptr;
  int capacity_ = 0, columns_ = ohmdem::ContactFlow::kColumns;
};

}  // namespace LAMMPS_NS

#endif
