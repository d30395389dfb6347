// SPDX-License-Identifier: GPL-2.0-or-later
// Per-atom state of an ohmdem fix, kept in a `fix property/atom` (vector style) so that it
// migrates with the atoms between processes and is written to restart files — the LIGGGHTS
// idiom. A fix re-defined after read_restart with the same ID gets its state back.
#ifndef OHMDEM_STYLE_PERATOM_STATE_H
#define OHMDEM_STYLE_PERATOM_STATE_H

#include <string>
#include <vector>

#include "fix_property_atom.h"
#include "modify.h"

namespace ohmdem {

// Creates the property/atom `name` with one column per default value, unless it exists.
inline void create_peratom_state(LAMMPS_NS::Modify *modify, const std::string &name,
                                 const std::vector<std::string> &defaults, const char *caller)
{
  if (modify->find_fix_property(name.c_str(), "property/atom", "vector", 0, 0, caller, false))
    return;
  std::vector<const char *> arg = {
      name.c_str(), "all", "property/atom", name.c_str(), "vector", "yes", "no", "no"};
  for (const auto &d : defaults) arg.push_back(d.c_str());
  modify->add_fix_property_atom(static_cast<int>(arg.size()), const_cast<char **>(arg.data()),
                                caller);
}

inline LAMMPS_NS::FixPropertyAtom *find_peratom_state(LAMMPS_NS::Modify *modify,
                                                      const std::string &name, const char *caller)
{
  return static_cast<LAMMPS_NS::FixPropertyAtom *>(
      modify->find_fix_property(name.c_str(), "property/atom", "vector", 0, 0, caller));
}

}  // namespace ohmdem

#endif
