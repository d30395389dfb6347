// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant: the bearing's impedance at the excitation
// frequency, in closed form (each ball its two contacts in series, the balls in parallel),
// from this step's race contacts, ball and ring velocities. The physics is in
// lib/lubrication (doc/lubricated_contact.md); this file gathers the inputs per ball and
// reduces over processes. Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_LUBRICATED_BEARING_H
#define OHMDEM_STYLE_LUBRICATED_BEARING_H

#include <string>
#include <vector>

#include "ELECTRIC/resistance_context.h"
#include "common/ordered_reduce.h"
#include "conduction/conduction_model.h"
#include "lubrication/lubricant.h"
#include "pointers.h"

namespace LAMMPS_NS {

// The keywords of compute network/resistance that concern the lubricant.
struct LubricationSettings {
  std::string lubricant = "none";  // a catalog name, a path, or none
  double temperature = 40.0;       // C
  double roughness = -1.0;         // composite RMS roughness (m); required with a lubricant
  double fexc = -1.0;              // excitation frequency (Hz); required with a lubricant
  double wetted = -1.0;            // wetted radius around a contact (m); required
  double excitation = 1.0;         // voltage amplitude across the bearing (V)
  double breakdown = 0.0;          // breakdown field of the film (V/m); 0: no breakdown
  bool on() const { return lubricant != "none"; }
};

// The global outputs 9-15 of the compute.
struct LubricatedResult {
  double z_abs = 0, z_phase = 0, c_parallel = 0, r_parallel = 0;
  double hmin_inner = 0, hmin_outer = 0, lambda_min = 0;
  static constexpr int kSize = 7;
};

class LubricatedBearing : protected Pointers {
 public:
  // Reads the lubricant (throws LubricantError with the message for the user).
  LubricatedBearing(LAMMPS *lmp, const LubricationSettings &settings);
  const ohmdem::lubrication::LubricantState &state() const { return state_; }
  const std::string &path() const { return path_; }
  // init(): both electrodes must be races (checked by the compute). The geometry is read at
  // the first evaluation of the run.
  void init(const ResistanceContext &context);
  // Collective: this step's impedance.
  LubricatedResult evaluate(const ResistanceContext &context);

 private:
  void set_geometry(const ResistanceContext &context);

  LubricationSettings settings_;
  bool geometry_ready_ = false;
  std::string path_;
  ohmdem::lubrication::LubricantState state_;
  ohmdem::BallBetweenRaces dry_;                // the dry conductance of a ball (the metallic path)
  std::vector<ohmdem::TaggedValues<2>> balls_;  // Re Y, Im Y per ball
  ohmdem::OrderedGather<2> gather_;
};

}  // namespace LAMMPS_NS

#endif
