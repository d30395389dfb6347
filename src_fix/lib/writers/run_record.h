// SPDX-License-Identifier: GPL-2.0-or-later
// Which run a restart file belongs to. A run folder counts the runs started in it
// (FOLDER/.ohmdem.run: "run K"); fix run/record writes into every restart file the run's
// number and its parameters (its run.json); a resume compares them with the folder's run and
// the parameters it is given, so that a restart of another run, or other parameters, are
// never taken silently (doc/run_status.md, "On restart"). Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_RUN_RECORD_H
#define OHMDEM_RUN_RECORD_H

#include <string>
#include <utility>
#include <vector>

namespace ohmdem {

struct RunRecord {
  long run = 0;            // the run's number in its folder (0: unknown)
  std::string parameters;  // its run.json
};

// The record as the bytes of fix run/record's restart state, and back (false: not a record).
std::string encode_run_record(const RunRecord &record);
bool decode_run_record(const std::string &bytes, RunRecord &record);

// FOLDER's run number (0 when no run was started in it), and its new value.
long folder_run_number(const std::string &folder);
std::string set_folder_run_number(const std::string &folder, long run);

// A new run begins in FOLDER: its number goes up by one, and the FILES (names in FOLDER) that
// the previous run left are renamed NAME.previous (replacing older ones), so that "the newer
// of restart.a and restart.b" is never another run's. `renamed` lists them. "" or the error.
std::string begin_new_run(const std::string &folder, const std::vector<std::string> &files,
                          long &run, std::vector<std::string> &renamed);

// The members of a run.json that are the run's parameters: its progress (status,
// time_reached, error), its length (tend), the build (ohmdem_version), restart_changes and what
// the run measured (contact_angle, contact_angle_nominal) left out.
bool is_run_parameter(const std::string &key);

struct ParameterChange {
  std::string key, before, after;  // values as JSON text ("" when absent)
};
// The parameters of `before` (a run.json text) that `after` (members as JSON text) changes,
// in `after`'s order, then those it lacks. Throws json::JsonError when `before` is no flat
// JSON object.
std::vector<ParameterChange> changed_parameters(
    const std::string &before, const std::vector<std::pair<std::string, std::string>> &after);

}  // namespace ohmdem

#endif
