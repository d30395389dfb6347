// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command check_variables (doc/command_check_variables.md)

     check_variables NAME FORM [NAME FORM ...]

   Each variable NAME defined so far (index or string style: what -var and a case
   table give) must have FORM (src_fix/lib/writers/variable_forms.h); the first that
   has not stops the run, on every process, with "deck variable NAME: expected ...,
   got '...'". A variable not defined yet is left to the deck's own default.
------------------------------------------------------------------------- */

#include "OUTPUT/command_check_variables.h"

#include <stdexcept>
#include <string>

#include "error.h"
#include "input.h"
#include "variable.h"
#include "writers/variable_forms.h"

using namespace LAMMPS_NS;

CheckVariables::CheckVariables(LAMMPS *lmp) : Pointers(lmp) {}

void CheckVariables::command(int narg, char **arg)
{
  if (narg < 2 || narg % 2 != 0)
    error->all(FLERR,
               "check_variables: expects NAME FORM pairs (e.g. tend number start "
               "new|restart)");
  Variable *v = input->variable;
  auto kind = [v](const std::string &name) {
    const int i = v->find(const_cast<char *>(name.c_str()));
    if (i < 0) return ohmdem::VariableKind::None;
    return v->equalstyle(i) ? ohmdem::VariableKind::Equal : ohmdem::VariableKind::Other;
  };
  for (int k = 0; k < narg; k += 2) {
    const std::string name = arg[k], form = arg[k + 1];
    if (!ohmdem::valid_form(form))
      error->all(FLERR, ("check_variables: '" + form + "' (for " + name +
                         ") is not a form: number, v_equal, path, folder, word or literal words, "
                         "joined by |")
                            .c_str());
    const int i = v->find(arg[k]);
    if (i < 0 || v->equalstyle(i)) continue;  // not given, or a formula LIGGGHTS checks
    const char *value = v->retrieve(arg[k]);
    if (!value) continue;
    const std::string bad = ohmdem::form_mismatch(form, value, kind);
    if (!bad.empty()) error->all(FLERR, ("deck variable " + name + ": " + bad).c_str());
  }
}
