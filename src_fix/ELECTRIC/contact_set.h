// SPDX-License-Identifier: GPL-2.0-or-later
// The conducting contacts of a group on the current step, for the electrical computes:
// ball–race contacts from every fix bearing/race, and particle–particle contacts from the
// granular pair style (the normal force LIGGGHTS' pair style applies, read through an
// internal `compute pair/gran/local`). Contact areas come from the normal force (rigid Hertz
// areas, paper eqs. 2–5) in the `greenwood` or `exact` mode of hertz_contact.h.
//
// Each contact is an ohmdem::ContactRecord (electric/network_builder.h), the record every
// evaluation path of compute network/resistance reads and sends over MPI.
// Adapter code (LIGGGHTS types); the geometry and the network are plain C++ kernels.
#ifndef OHMDEM_STYLE_CONTACT_SET_H
#define OHMDEM_STYLE_CONTACT_SET_H

#include <memory>
#include <string>
#include <vector>

#include "contact/hertz_contact.h"
#include "conduction/network_builder.h"
#include "lmptype.h"
#include "pointers.h"

namespace LAMMPS_NS {

class FixBearingRace;
class ComputePairGranLocal;

class ContactSet : protected Pointers {
 public:
  ContactSet(LAMMPS *lmp, const std::string &owner_id, ohmdem::AreaModel model, bool use_pair);
  ~ContactSet();
  // Finds the race fixes and materials; creates the pair/gran/local compute when asked for.
  void init(int groupbit);
  // The contacts of this process with fn > 0, each contact on exactly one process; both
  // particles of a pair contact are in the group. A record's `tag` is a particle of the
  // group owned by this process, `other` the other particle (0 for a race), `race` the
  // index in races() of a ball–race contact (-1 otherwise), `a`, `b` the contact ellipse.
  void collect(std::vector<ohmdem::ContactRecord> &out);
  const std::vector<FixBearingRace *> &races() const { return races_; }
  ohmdem::AreaModel area_model() const { return model_; }  // greenwood or exact
  // Contact geometry of race k in the chosen area mode (valid once the races are set up).
  const ohmdem::HertzContact &race_geometry(int k);
  bool uses_pair() const { return pgl_ != nullptr; }

 private:
  void collect_races(std::vector<ohmdem::ContactRecord> &out);
  void collect_pairs(std::vector<ohmdem::ContactRecord> &out);

  std::string owner_id_;
  ohmdem::AreaModel model_;
  bool want_pair_;
  int groupbit_ = 0;
  std::vector<FixBearingRace *> races_;
  std::vector<ohmdem::HertzContact> race_hertz_;  // race contact geometry in the area mode
  ComputePairGranLocal *pgl_ = nullptr;
};

}  // namespace LAMMPS_NS

#endif
