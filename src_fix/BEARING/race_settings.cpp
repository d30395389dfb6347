// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/race: its arguments (the keywords, what each load mode
   needs, the load vector) and the variables omega/force may name. The step is in
   fix_bearing_race.cpp, the checks that stop a run in fix_bearing_race_checks.cpp.
------------------------------------------------------------------------- */

#include <cmath>
#include <cstring>
#include <string>

#include "BEARING/fix_bearing_race.h"
#include "atom.h"
#include "error.h"
#include "input.h"
#include "modify.h"
#include "support/args.h"
#include "update.h"
#include "variable.h"

using namespace LAMMPS_NS;

void FixBearingRace::parse(int narg, char **arg)
{
  ohmdem::StyleArgs a(error, "fix bearing/race", narg, arg, 3);
  const std::string side = a.word("side", "inner or outer as first argument");
  if (side == "inner")
    inner_ = true;
  else if (side == "outer")
    inner_ = false;
  else
    a.fail("side", "inner or outer as first argument", side.c_str());

  bool have_radius = false, have_groove = false, have_type = false;
  bool have_force = false, have_settle = false, have_interference = false;
  double dir_x = 0.0, dir_y = -1.0;
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "radius") {
      radius_ = a.positive(kw, "the race radius at the groove bottom, a positive length (m)");
      have_radius = true;
    } else if (kw == "groove") {
      groove_ = a.positive(kw, "the groove radius of curvature, a positive length (m)");
      have_groove = true;
    } else if (kw == "type") {
      race_type_ = a.integer(kw, "the race material type, an atom type 1..ntypes", 1, 1 << 30);
      have_type = true;
    } else if (kw == "centre" || kw == "center") {
      cx_ = axis_x_ = a.number(kw, "two coordinates x y (m)");
      cy_ = axis_y_ = a.number(kw, "two coordinates x y (m)");
    } else if (kw == "omega") {
      if (std::strncmp(a.peek(), "v_", 2) == 0)
        omega_var_ = a.word(kw, "v_NAME") + 2;  // an equal-style variable, each step
      else
        omega_ = a.number(kw, "the ring angular speed about z (rad/s), or v_NAME");
    } else if (kw == "ramp") {
      ramp_ = a.non_negative(kw, "the duration of the linear speed ramp, a time >= 0 (s)");
    } else if (kw == "omega_start") {
      omega_start_ = a.number(kw, "the ring angular speed at the start of the ramp (rad/s)");
    } else if (kw == "mass") {
      ring_mass_ = a.positive(kw, "the ring mass, a positive mass (kg)");
    } else if (kw == "damp") {
      ring_damp_ = a.non_negative(kw, "the ring damping coefficient >= 0 (N s/m)");
    } else if (kw == "load") {
      const std::string mode = a.word(kw, "none, force, fixed or radial");
      if (mode == "none")
        load_ = Load::None;
      else if (mode == "force")
        load_ = Load::Force;
      else if (mode == "fixed")
        load_ = Load::Fixed;
      else if (mode == "radial")
        load_ = Load::Radial;
      else
        a.fail(kw, "none, force, fixed or radial", mode.c_str());
      // Shorthand: "load force F" / "load radial F" = "load force force F".
      if ((load_ == Load::Force || load_ == Load::Radial) && a.next_is_number()) {
        load_force_ = a.positive("load", "the load magnitude F > 0 (N)");
        have_force = true;
      }
    } else if (kw == "force") {
      if (std::strncmp(a.peek(), "v_", 2) == 0)
        force_var_ = a.word(kw, "v_NAME") + 2;  // an equal-style variable, each step
      else
        load_force_ = a.positive(kw, "the load magnitude F > 0 (N), or v_NAME");
      have_force = true;
    } else if (kw == "settle") {
      settle_time_ = a.positive(kw, "the settling time T > 0 (s)");
      have_settle = true;
    } else if (kw == "interference") {
      interference_ = a.number(kw, "a radial interference toward the balls (m)");
      have_interference = true;
    } else if (kw == "direction") {
      dir_x = a.number(kw, "the radial load direction dx dy");
      dir_y = a.number(kw, "the radial load direction dx dy");
      if (!(std::hypot(dir_x, dir_y) > 0.0)) a.fail(kw, "a non-zero direction dx dy", "0 0");
    } else {
      a.unknown(kw.c_str(),
                "radius groove type centre omega ramp omega_start load force settle interference "
                "direction mass damp");
    }
  }
  if (!have_radius) a.fail("radius", "a value: the keyword is required", "nothing");
  if (!have_groove) a.fail("groove", "a value: the keyword is required", "nothing");
  if (!have_type) a.fail("type", "a value: the keyword is required", "nothing");
  if (race_type_ > atom->ntypes)
    a.fail("type", "an atom type between 1 and ntypes = " + std::to_string(atom->ntypes),
           std::to_string(race_type_).c_str());
  check_load(a, have_force, have_settle, have_interference, dir_x, dir_y);
}

// Which load keywords each mode needs, and the load vector of a radial load.
void FixBearingRace::check_load(ohmdem::StyleArgs &a, bool have_force, bool have_settle,
                                bool have_interference, double dir_x, double dir_y)
{
  if ((load_ == Load::Force || load_ == Load::Radial) && !have_force)
    a.fail("force", "a value: load force and load radial need 'force F'", "nothing");
  if (load_ == Load::Fixed) {
    if (have_settle == have_interference)
      a.fail("load fixed", "exactly one of 'settle T' (with 'force F') or 'interference U'",
             have_settle ? "both" : "neither");
    if (have_settle && !have_force)
      a.fail("force", "a value: load fixed with settle needs 'force F'", "nothing");
    if (have_settle)
      load_ = Load::Settle;
    else
      u_ = interference_;
  }
  {
    const double n = std::hypot(dir_x, dir_y);
    dir_ux_ = dir_x / n;
    dir_uy_ = dir_y / n;
  }
  if (load_ == Load::Radial) {
    load_fx_ = load_force_ * dir_ux_;
    load_fy_ = load_force_ * dir_uy_;
  }
  const bool dynamic = load_ == Load::Force || load_ == Load::Settle || load_ == Load::Radial;
  if (dynamic && ring_mass_ <= 0.0)
    a.fail("mass", "a positive ring mass (kg): required by load force, fixed settle and radial",
           "nothing");
}

// omega v_NAME / force v_NAME: the variables must exist and be equal-style.
void FixBearingRace::find_variables()
{
  auto find = [&](const std::string &name, const char *kw) {
    if (name.empty()) return -1;
    const int i = input->variable->find(const_cast<char *>(name.c_str()));
    if (i < 0 || !input->variable->equalstyle(i)) {
      const std::string msg = std::string("keyword '") + kw + "' expects v_NAME of an " +
                              "equal-style variable, got 'v_" + name + "' (" +
                              (i < 0 ? "no such variable" : "not equal-style") + ")";
      error->fix_error(FLERR, this, msg.c_str());
    }
    return i;
  };
  omega_ivar_ = find(omega_var_, "omega");
  force_ivar_ = find(force_var_, "force");
}

// The values of this step (the variables may use time, step or other outputs).
void FixBearingRace::evaluate_variables()
{
  if (omega_ivar_ < 0 && force_ivar_ < 0) return;
  modify->clearstep_compute();
  if (omega_ivar_ >= 0) {
    omega_now_ = input->variable->compute_equal(omega_ivar_);
    if (!std::isfinite(omega_now_)) {
      const std::string msg = "variable '" + omega_var_ + "' of keyword 'omega' gave " +
                              std::to_string(omega_now_) + " at step " +
                              std::to_string(update->ntimestep) + " (a finite speed, rad/s)";
      error->fix_error(FLERR, this, msg.c_str());
    }
  }
  if (force_ivar_ >= 0) {
    const double F = input->variable->compute_equal(force_ivar_);
    if (!(F >= 0.0) || !std::isfinite(F)) {
      const std::string msg = "variable '" + force_var_ + "' of keyword 'force' gave " +
                              std::to_string(F) + " at step " + std::to_string(update->ntimestep) +
                              " (a finite load >= 0, N)";
      error->fix_error(FLERR, this, msg.c_str());
    }
    load_force_ = F;
    if (load_ == Load::Radial) {
      load_fx_ = load_force_ * dir_ux_;
      load_fy_ = load_force_ * dir_uy_;
    }
  }
  modify->addstep_compute(update->ntimestep + 1);
}
