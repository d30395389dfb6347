// SPDX-License-Identifier: GPL-2.0-or-later
// The ohmdem styles work in SI units (lengths in m, forces in N, conductivities in S/m, the
// Hertz and Holm laws with SI constants): a deck in other units stops with a clear error.
#ifndef OHMDEM_SUPPORT_REQUIRE_SI_H
#define OHMDEM_SUPPORT_REQUIRE_SI_H

#include <cstring>
#include <string>

#include "error.h"
#include "lammps.h"
#include "update.h"

namespace ohmdem {

inline void require_si_units(LAMMPS_NS::LAMMPS *lmp, const char *what)
{
  const char *units = lmp->update->unit_style;
  if (units && std::strcmp(units, "si") == 0) return;
  const std::string msg = std::string(what) + ": requires 'units si' (lengths in m, forces in N, " +
                          "conductivities in S/m), got 'units " + (units ? units : "?") + "'";
  lmp->error->all(FLERR, msg.c_str());
}

}  // namespace ohmdem

#endif
