// SPDX-License-Identifier: GPL-2.0-or-later
// Finding run folders (a folder holding signal.txt and run.json) and their swept parameters (the
// scalar keys of run.json): what `ohmdem-post collect` gathers into one table.
#ifndef OHMDEM_POST_IO_RUN_FOLDERS_H
#define OHMDEM_POST_IO_RUN_FOLDERS_H

#include <string>
#include <utility>
#include <vector>

#include "io/json.h"

namespace ohmdem::post {

struct RunFolders {
  std::vector<std::string> runs;  // display paths, sorted (natural_less), no duplicates
  std::vector<std::pair<std::string, std::string>> skipped;  // path, reason (in scan order)
};

// A run is a folder holding run.json and signal.txt (or signal.npy). Each path given is a run
// folder, a run's signal file (its folder is the run), or - with
// `recursive` - a folder searched with its subfolders (hidden ones excepted, symbolic links to
// folders not followed). Skipped, with the reason: a given path that is not a run (does not
// exist, lacks signal.txt or run.json; with `recursive`: holds no run at all), and, while
// searching, a folder holding one of the two files but not the other. The same folder reached
// twice (given twice, or under two given folders) counts once, under its smallest display
// path, so the result does not depend on the order of `paths`. A sweep root (a folder that is no
// run but holds sweep_cases.csv, doc/case_table.md) gives, without `recursive`, the case
// folders it lists; a listed case that is not a run is skipped with its line number.
RunFolders find_run_folders(const std::vector<std::string> &paths, bool recursive);

// A run's signal file: RUN/signal.txt, or RUN/signal.npy when only that one exists (the deck's
// -var signal_format npy).
std::string run_signal_file(const std::string &run);

// Natural order of paths: runs of digits compare by value ("size_2" < "size_10"), then
// byte-wise as a tie-break. A strict weak ordering.
bool natural_less(const std::string &a, const std::string &b);

// The scalar members (numbers, strings, booleans) of the JSON object in `path`, in file order;
// null members are left out, arrays and objects are listed in `nonscalar`. Throws Error on a
// missing file or invalid JSON.
using RunParameters = std::vector<std::pair<std::string, Json>>;
RunParameters run_parameters(const std::string &path,
                             std::vector<std::string> *nonscalar = nullptr);

// The value of `key` in `params`, nullptr if absent.
const Json *find_parameter(const RunParameters &params, const std::string &key);

// The parameter columns of a set of runs: every key some run has, in case-insensitive order
// ("area" < "F" < "load", byte order on a tie); with `varying_only`, only the keys whose value
// differs between the runs (a run lacking the key differs from one having it).
std::vector<std::string> parameter_keys(const std::vector<const RunParameters *> &runs,
                                        bool varying_only);

}  // namespace ohmdem::post

#endif
