// SPDX-License-Identifier: GPL-2.0-or-later
// Per-type material properties from `fix property/global ... peratomtype[pair]`, the way the
// stock granular models read them. Shared by the ohmdem styles (adapter code: LIGGGHTS types).
#ifndef OHMDEM_MATERIAL_TABLE_H
#define OHMDEM_MATERIAL_TABLE_H

#include "atom.h"
#include "contact/hertz_contact.h"
#include "fix_property_global.h"
#include "modify.h"

namespace ohmdem {

class MaterialTable {
 public:
  // Looks up the properties; LIGGGHTS stops with its own error naming a missing one.
  // Optional properties (restitution, friction) are looked up only when asked for.
  MaterialTable(LAMMPS_NS::LAMMPS *lmp, const char *caller, bool restitution, bool friction)
  {
    const int nt = lmp->atom->ntypes;
    LAMMPS_NS::Modify *m = lmp->modify;
    E_ = find(m, "youngsModulus", "peratomtype", nt, 0, caller);
    nu_ = find(m, "poissonsRatio", "peratomtype", nt, 0, caller);
    if (restitution) e_ = find(m, "coefficientRestitution", "peratomtypepair", nt, nt, caller);
    if (friction) mu_ = find(m, "coefficientFriction", "peratomtypepair", nt, nt, caller);
  }
  // Types are 1-based atom types.
  double E(int t) const { return E_->compute_vector(t - 1); }
  double nu(int t) const { return nu_->compute_vector(t - 1); }
  double E_eff(int t1, int t2) const { return effective_modulus(E(t1), nu(t1), E(t2), nu(t2)); }
  double G_eff(int t1, int t2) const
  {
    return effective_shear_modulus(E(t1), nu(t1), E(t2), nu(t2));
  }
  double restitution(int t1, int t2) const { return e_->compute_array(t1 - 1, t2 - 1); }
  double friction(int t1, int t2) const { return mu_->compute_array(t1 - 1, t2 - 1); }

 private:
  static LAMMPS_NS::FixPropertyGlobal *find(LAMMPS_NS::Modify *m, const char *name,
                                            const char *kind, int n1, int n2, const char *caller)
  {
    return static_cast<LAMMPS_NS::FixPropertyGlobal *>(
        m->find_fix_property(name, "property/global", kind, n1, n2, caller));
  }
  LAMMPS_NS::FixPropertyGlobal *E_ = nullptr, *nu_ = nullptr, *e_ = nullptr, *mu_ = nullptr;
};

}  // namespace ohmdem

#endif
