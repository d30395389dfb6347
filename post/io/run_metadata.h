// SPDX-License-Identifier: GPL-2.0-or-later
// The run's metadata written by our decks next to signal.txt (run.json): bearing, speed, time
// step, sliding-phase end. Every field is optional; present fields are type-checked.
#ifndef OHMDEM_POST_RUN_METADATA_H
#define OHMDEM_POST_RUN_METADATA_H

#include <optional>
#include <string>

namespace ohmdem::post {

struct RunMetadata {
  std::string path;  // empty when no metadata was found
  // load: force, fixed or radial; a model 3d run's "shaft" (its shaft under Fr, Fa, M, the
  // outer ring held or on its housing) reads as the load zone it makes: radial with Fr > 0,
  // else force (an axial load or preload loads every ball alike).
  std::optional<std::string> bearing, defect, load;
  std::optional<std::string> catalog_name;  // the -var bearing NAME the run started from
  std::optional<double> omega_inner;        // shaft angular speed (rad/s)
  std::optional<double> nb, db, dp;         // ball count, ball and pitch diameters (m)
  std::optional<double> dext, dinn;         // race diameters at the groove bottom (m)
  std::optional<double> rc_ext, rc_inn;     // groove radii (m)
  std::optional<double> contact_angle;      // degrees
  std::optional<double> dt;                 // engine time step (s)
  std::optional<double> size_deg;           // the defect size set in the deck (for reference only)
  std::optional<double> t_sliding_end;      // end of the sliding phase (s)
  // how the run ended: "finished", "interrupted" or "failed" (absent: a run older than the
  // field, taken as finished), and the simulated time it reached (s)
  std::optional<std::string> status;
  std::optional<double> time_reached;
  bool finished() const { return !status || *status == "finished"; }

  bool present() const { return !path.empty(); }
};

RunMetadata read_run_metadata(const std::string &path);  // throws Error on bad JSON or types
// "<directory of signal_path>/run.json" if that file exists, else "" (also for "-", standard
// input, which has no folder).
std::string find_run_metadata(const std::string &signal_path);

}  // namespace ohmdem::post

#endif
