// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: the equal-style variables that `omega v_NAME` and `force v_NAME` name,
// found at setup and evaluated at the start of each step. Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_RACE_VARIABLES_H
#define OHMDEM_STYLE_RACE_VARIABLES_H

#include <string>

#include "pointers.h"

namespace LAMMPS_NS {

class Fix;

class RaceVariables : protected Pointers {
 public:
  // Variable names without "v_" ("" for none); errors name `fix`.
  RaceVariables(LAMMPS *lmp, Fix *fix, std::string omega, std::string force);
  // The variables must exist and be equal-style.
  void find();
  bool any() const { return omega_ivar_ >= 0 || force_ivar_ >= 0; }
  bool sets_omega() const { return omega_ivar_ >= 0; }
  bool sets_force() const { return force_ivar_ >= 0; }
  // The values of this step (the variables may use time, step or other outputs): a finite
  // speed (rad/s) and a finite load >= 0 (N); untouched for a keyword without a variable.
  void evaluate(double &omega, double &force);

 private:
  Fix *fix_;
  std::string omega_var_, force_var_;
  int omega_ivar_ = -1, force_ivar_ = -1;
};

}  // namespace LAMMPS_NS

#endif
