// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: what its evaluation paths share, set by the compute (keywords
// in its constructor, the rest in init()) and read by every path (resistance_path.h): the
// contact set, the model, the conductivities, the electrodes, the group and the current.
// Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_RESISTANCE_CONTEXT_H
#define OHMDEM_STYLE_RESISTANCE_CONTEXT_H

#include <memory>
#include <string>
#include <vector>

#include "conduction/conduction_model.h"
#include "conduction/network_builder.h"

namespace LAMMPS_NS {

class Atom;
class ContactSet;

enum class ElectrodeKind { Race, Group };

struct Electrode {
  ElectrodeKind kind = ElectrodeKind::Race;
  std::string name;
  int index = -1;  // race: index in the contact set's races; group: group bit

  int group_bit() const { return kind == ElectrodeKind::Group ? index : 0; }
  // The electrode's node: a race's, or that of the members of the group (`member`).
  ohmdem::NodeKey node(ohmdem::Membership member) const
  {
    return kind == ElectrodeKind::Race ? ohmdem::race_node(index) : ohmdem::member_node(member);
  }
};

struct ResistanceContext {
  ContactSet *contacts = nullptr;
  ohmdem::ConductionModel model;   // from the keyword `model` (conduction_model.h's table)
  std::vector<double> gamma_type;  // conductivity of each atom type (S/m), 1-based
  Electrode high, low;
  int groupbit = 0;
  double current = 0;  // A, into the high electrode

  // Both electrodes are races: the closed form may apply.
  bool races_are_electrodes() const
  {
    return high.kind == ElectrodeKind::Race && low.kind == ElectrodeKind::Race;
  }
  int race_electrode(int race) const;  // +1 high, -1 low, 0 neither
  // The conductivity of each race of the contact set (S/m); `out` is refilled.
  void gamma_race(std::vector<double> &out) const;
  // The record of local or ghost atom i (which electrode group it belongs to, if any).
  ohmdem::ParticleRecord particle(const Atom &atom, int i) const;
};

}  // namespace LAMMPS_NS

#endif
