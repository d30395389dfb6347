// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: its arguments (the keywords, what each load mode needs, the load
// vector); see race_settings.h.
#include "BEARING/race_settings.h"

#include <cmath>
#include <cstring>
#include <string>

#include "BEARING/race_settings_3d.h"
#include "support/args.h"

namespace ohmdem {

namespace {

// Which load keywords each mode needs, and the load vector of a radial load.
void check_load(StyleArgs &a, RaceSettings &s, bool have_force, bool have_settle,
                bool have_interference, double dir_x, double dir_y)
{
  if ((s.load == RaceLoad::Force || s.load == RaceLoad::Radial) && !have_force)
    a.fail("force", "a value: load force and load radial need 'force F'", "nothing");
  if (s.load == RaceLoad::Fixed) {
    if (have_settle == have_interference)
      a.fail("load fixed", "exactly one of 'settle T' (with 'force F') or 'interference U'",
             have_settle ? "both" : "neither");
    if (have_settle && !have_force)
      a.fail("force", "a value: load fixed with settle needs 'force F'", "nothing");
    if (have_settle) s.load = RaceLoad::Settle;
  }
  {
    const double n = std::hypot(dir_x, dir_y);
    s.dir_ux = dir_x / n;
    s.dir_uy = dir_y / n;
  }
  if (s.load == RaceLoad::Radial) {
    s.load_fx = s.load_force * s.dir_ux;
    s.load_fy = s.load_force * s.dir_uy;
  }
  if (s.dynamic() && s.ring_mass <= 0.0)
    a.fail("mass",
           "a positive ring mass (kg): required by load force, fixed settle, radial and housing",
           "nothing");
}

}  // namespace

RaceSettings parse_race_settings(LAMMPS_NS::Error *error, int narg, char **arg, int ntypes)
{
  RaceSettings s;
  StyleArgs a(error, "fix bearing/race", narg, arg, 3);
  const std::string side = a.word("side", "inner or outer as first argument");
  if (side == "inner")
    s.inner = true;
  else if (side == "outer")
    s.inner = false;
  else
    a.fail("side", "inner or outer as first argument", side.c_str());

  bool have_radius = false, have_groove = false, have_type = false;
  bool have_force = false, have_settle = false, have_interference = false;
  double dir_x = 0.0, dir_y = -1.0;
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "radius") {
      s.radius = a.positive(kw, "the race radius at the groove bottom, a positive length (m)");
      have_radius = true;
    } else if (kw == "groove") {
      s.groove = a.positive(kw, "the groove radius of curvature, a positive length (m)");
      have_groove = true;
    } else if (kw == "type") {
      s.race_type = a.integer(kw, "the race material type, an atom type 1..ntypes", 1, 1 << 30);
      have_type = true;
    } else if (kw == "centre" || kw == "center") {
      s.centre_x = a.number(kw, "two coordinates x y (m)");
      s.centre_y = a.number(kw, "two coordinates x y (m)");
    } else if (kw == "omega") {
      if (std::strncmp(a.peek(), "v_", 2) == 0)
        s.omega_var = a.word(kw, "v_NAME") + 2;  // an equal-style variable, each step
      else
        s.omega = a.number(kw, "the ring angular speed about z (rad/s), or v_NAME");
    } else if (kw == "ramp") {
      s.ramp = a.non_negative(kw, "the duration of the linear speed ramp, a time >= 0 (s)");
    } else if (kw == "omega_start") {
      s.omega_start = a.number(kw, "the ring angular speed at the start of the ramp (rad/s)");
    } else if (kw == "mass") {
      s.ring_mass = a.positive(kw, "the ring mass, a positive mass (kg)");
    } else if (kw == "damp") {
      s.ring_damp = a.non_negative(kw, "the ring damping coefficient >= 0 (N s/m)");
    } else if (kw == "load") {
      const std::string mode = a.word(kw, "none, force, fixed or radial");
      if (mode == "none")
        s.load = RaceLoad::None;
      else if (mode == "force")
        s.load = RaceLoad::Force;
      else if (mode == "fixed")
        s.load = RaceLoad::Fixed;
      else if (mode == "radial")
        s.load = RaceLoad::Radial;
      else
        a.fail(kw, "none, force, fixed or radial", mode.c_str());
      // Shorthand: "load force F" / "load radial F" = "load force force F".
      if ((s.load == RaceLoad::Force || s.load == RaceLoad::Radial) && a.next_is_number()) {
        s.load_force = a.positive("load", "the load magnitude F > 0 (N)");
        have_force = true;
      }
    } else if (kw == "force") {
      if (std::strncmp(a.peek(), "v_", 2) == 0)
        s.force_var = a.word(kw, "v_NAME") + 2;  // an equal-style variable, each step
      else
        s.load_force = a.non_negative(kw, "the load magnitude F > 0 (N), or v_NAME");
      have_force = true;
    } else if (kw == "settle") {
      s.settle_time = a.positive(kw, "the settling time T > 0 (s)");
      have_settle = true;
    } else if (kw == "interference") {
      s.interference = a.number(kw, "a radial interference toward the balls (m)");
      have_interference = true;
    } else if (kw == "direction") {
      dir_x = a.number(kw, "the radial load direction dx dy");
      dir_y = a.number(kw, "the radial load direction dx dy");
      if (!(std::hypot(dir_x, dir_y) > 0.0)) a.fail(kw, "a non-zero direction dx dy", "0 0");
    } else if (!parse_race_keyword_3d(a, kw, s)) {
      a.unknown(kw.c_str(),
                "radius groove type centre omega ramp omega_start load force settle interference "
                "direction mass damp " +
                    std::string(race_keywords_3d()));
    }
  }
  if (!have_radius) a.fail("radius", "a value: the keyword is required", "nothing");
  if (!have_groove) a.fail("groove", "a value: the keyword is required", "nothing");
  if (!have_type) a.fail("type", "a value: the keyword is required", "nothing");
  if (s.race_type > ntypes)
    a.fail("type", "an atom type between 1 and ntypes = " + std::to_string(ntypes),
           std::to_string(s.race_type).c_str());
  check_race_3d(a, s);  // first: a 3D keyword under model 2d is named as such
  check_load(a, s, have_force, have_settle, have_interference, dir_x, dir_y);
  // Model 3d takes F = 0 (a ring under an axial load or moment alone); model 2d does not.
  if (have_force && s.force_var.empty() && !(s.load_force > 0.0) && !s.model3d.on)
    a.fail("force", "the load magnitude F > 0 (N), or v_NAME", "0");
  return s;
}

}  // namespace ohmdem
