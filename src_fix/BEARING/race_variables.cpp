// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: the variables omega/force may name; see race_variables.h.
#include "BEARING/race_variables.h"

#include <cmath>
#include <string>
#include <utility>

#include "error.h"
#include "fix.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

using namespace LAMMPS_NS;

RaceVariables::RaceVariables(LAMMPS *lmp, Fix *fix, std::string omega, std::string force)
    : Pointers(lmp), fix_(fix), omega_var_(std::move(omega)), force_var_(std::move(force))
{
}

void RaceVariables::find()
{
  auto find = [&](const std::string &name, const char *kw) {
    if (name.empty()) return -1;
    const int i = input->variable->find(const_cast<char *>(name.c_str()));
    if (i < 0 || !input->variable->equalstyle(i)) {
      const std::string msg = std::string("keyword '") + kw + "' expects v_NAME of an " +
                              "equal-style variable, got 'v_" + name + "' (" +
                              (i < 0 ? "no such variable" : "not equal-style") + ")";
      error->fix_error(FLERR, fix_, msg.c_str());
    }
    return i;
  };
  omega_ivar_ = find(omega_var_, "omega");
  force_ivar_ = find(force_var_, "force");
}

void RaceVariables::evaluate(double &omega, double &force)
{
  if (!any()) return;
  modify->clearstep_compute();
  if (omega_ivar_ >= 0) {
    omega = input->variable->compute_equal(omega_ivar_);
    if (!std::isfinite(omega)) {
      const std::string msg = "variable '" + omega_var_ + "' of keyword 'omega' gave " +
                              std::to_string(omega) + " at step " +
                              std::to_string(update->ntimestep) + " (a finite speed, rad/s)";
      error->fix_error(FLERR, fix_, msg.c_str());
    }
  }
  if (force_ivar_ >= 0) {
    const double F = input->variable->compute_equal(force_ivar_);
    if (!(F >= 0.0) || !std::isfinite(F)) {
      const std::string msg = "variable '" + force_var_ + "' of keyword 'force' gave " +
                              std::to_string(F) + " at step " + std::to_string(update->ntimestep) +
                              " (a finite load >= 0, N)";
      error->fix_error(FLERR, fix_, msg.c_str());
    }
    force = F;
  }
  modify->addstep_compute(update->ntimestep + 1);
}
