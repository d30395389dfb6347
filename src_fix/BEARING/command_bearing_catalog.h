// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command bearing_catalog: defines a deck's bearing variables from
   the bearing catalog (inputs/bearings), read in C++ (no shell).
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS

// clang-format off
CommandStyle(bearing_catalog,BearingCatalog)
// clang-format on

#else

#ifndef LMP_BEARING_CATALOG_COMMAND_H
#define LMP_BEARING_CATALOG_COMMAND_H

#include <string>
#include <utility>
#include <vector>

#include "pointers.h"

namespace LAMMPS_NS {

class BearingCatalog : protected Pointers {
 public:
  explicit BearingCatalog(LAMMPS *lmp);
  void command(int narg, char **arg);

 private:
  // WORD, or the value of the variable V when WORD is v_V.
  std::string value_of(const std::string &word, const char *what);
  [[noreturn]] void fail(const std::string &message);
  using Variables = std::vector<std::pair<std::string, std::string> >;
  // Rank 0's answer for every rank: the variables to define, or an error message.
  void broadcast(std::string &message, Variables &variables);
  void define_index(const std::string &name, const std::string &value);
};

}  // namespace LAMMPS_NS

#endif
#endif
