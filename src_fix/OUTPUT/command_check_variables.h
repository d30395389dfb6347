// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command check_variables: a deck's variables checked against their
   forms before LIGGGHTS parses them (doc/command_check_variables.md).
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS

// clang-format off
CommandStyle(check_variables,CheckVariables)
// clang-format on

#else

#ifndef LMP_CHECK_VARIABLES_COMMAND_H
#define LMP_CHECK_VARIABLES_COMMAND_H

#include "pointers.h"

namespace LAMMPS_NS {

class CheckVariables : protected Pointers {
 public:
  explicit CheckVariables(LAMMPS *lmp);
  void command(int narg, char **arg);
};

}  // namespace LAMMPS_NS

#endif
#endif
