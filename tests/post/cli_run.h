// SPDX-License-Identifier: GPL-2.0-or-later
// The command-line tests' helpers: run ohmdem-post (or a shell line) and read what it printed,
// and a run folder as our decks write it.
#ifndef OHMDEM_TESTS_POST_CLI_RUN_H
#define OHMDEM_TESTS_POST_CLI_RUN_H

#include <string>

namespace ohmdem::post::test {

struct CliRun {
  int status = -1;
  std::string out;  // standard output and error together
};

// Runs a shell command line (stdout and stderr together).
CliRun shell(const std::string &command);
// Runs `ohmdem-post ARGS`.
CliRun run(const std::string &args);
// A run folder under the tests' temporary folder as our decks write it: signal.txt (R at 1 MHz
// after a 5 ms sliding phase at another level, a 6208 defect of `kind` at 20 dB) and run.json.
std::string make_run_dir(const std::string &name, const std::string &kind);

}  // namespace ohmdem::post::test

#endif
