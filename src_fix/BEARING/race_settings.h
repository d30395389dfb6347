// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: its arguments as a value (the keywords of doc/fix_bearing_race.md),
// filled and checked once by parse_race_settings(); the fix keeps it unchanged for the run.
#ifndef OHMDEM_STYLE_RACE_SETTINGS_H
#define OHMDEM_STYLE_RACE_SETTINGS_H

#include <string>

namespace LAMMPS_NS {
class Error;
}

namespace ohmdem {

// `load fixed` with `settle` is Settle.
enum class RaceLoad { None, Force, Fixed, Settle, Radial };

struct RaceSettings {
  bool inner = true;
  double radius = 0, groove = 0;  // race radius at the groove bottom, groove radius (m)
  int race_type = 0;
  double centre_x = 0, centre_y = 0;  // the bearing axis (m)
  double omega = 0, ramp = 0;         // rad/s, s
  double omega_start = 0;  // the ramp goes from omega_start to omega (run-up or coast-down)
  // omega v_NAME / force v_NAME: equal-style variables (names without "v_"), each step
  std::string omega_var, force_var;
  RaceLoad load = RaceLoad::None;
  double load_force = 0;            // force / settle / radial: F (N)
  double load_fx = 0, load_fy = 0;  // radial: the load vector (N)
  double dir_ux = 0, dir_uy = -1;   // unit load direction (outputs along/across it)
  double interference = 0;          // fixed: imposed radial interference (m)
  double settle_time = 0;           // settle: force control until this time (s)
  double ring_mass = 0, ring_damp = 0;

  // model 3d (race_settings_3d.cpp; doc/fix_bearing_race.md "Model 3d"): the race is a torus,
  // and a ring under load radial is free in space (its centre moves, its axis tilts).
  struct Model3d {
    bool on = false;
    double clearance = 0;          // radial internal clearance of the bearing (m)
    double alpha0 = 0;             // nominal contact angle (rad)
    double shoulder = 0;           // largest contact angle the groove holds (rad), set by parse
    double axial = 0, moment = 0;  // load radial: axial force (N), moment about z x d (N m)
    bool preload_set = false;      // load radial: the axial position held at `preload` instead
    double preload = 0;            // (m)
    double tilt_inertia = 0;       // kg m^2 (0: mass * radius^2 / 2)
    double tilt_damp = -1;         // N m s (< 0: damp * radius^2 / 2)
    double housing = 0;            // outer ring: the housing's stiffness (N/m; 0: the ring held)
    int given = 0;                 // which of its keywords were given (race_settings_3d.cpp)
  } model3d;

  // The ring's radius or centre moves under a force: it has a mass.
  bool dynamic() const
  {
    return load == RaceLoad::Force || load == RaceLoad::Settle || load == RaceLoad::Radial ||
           on_housing();
  }
  // Model 3d, outer ring: its centre free in the plane on the housing's spring.
  bool on_housing() const { return model3d.housing > 0.0; }
};

// The arguments after "fix ID group bearing/race"; stops the run (error->all) with the
// keyword and the expected form on anything wrong. `ntypes`: the atom types of the run.
RaceSettings parse_race_settings(LAMMPS_NS::Error *error, int narg, char **arg, int ntypes);

}  // namespace ohmdem

#endif
