// SPDX-License-Identifier: GPL-2.0-or-later
// Run folders as our decks and sweeps write them, for the tests of finding run folders
// (io/run_folders) and of `ohmdem-post collect`.
#ifndef OHMDEM_TESTS_POST_RUN_FOLDER_FIXTURES_H
#define OHMDEM_TESTS_POST_RUN_FOLDER_FIXTURES_H

#include <string>

namespace ohmdem::post::test {

// A fresh (emptied) folder for one test under the tests' temporary folder.
std::string fresh_dir(const std::string &name);
// A run folder: signal.txt ("# time R n_masked", 100 kHz) and run.json (none if `json` is
// empty). R is a level with a pulse while n_masked > 0 (every `period` samples, `width` long)
// and a deterministic ripple; `nan_row` >= 0 puts a NaN there.
void make_run(const std::string &dir, const std::string &json, int n = 2000, int period = 40,
              int width = 4, double level = 1.39, int nan_row = -1);
// The study-like layout of several tests: three runs with differing keys, a folder without
// run.json, a container folder; returns its root.
std::string make_sweep(const std::string &name);

}  // namespace ohmdem::post::test

#endif
