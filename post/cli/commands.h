// SPDX-License-Identifier: GPL-2.0-or-later
// The dispatch table of ohmdem-post: one entry per command.
#ifndef OHMDEM_POST_CLI_COMMANDS_H
#define OHMDEM_POST_CLI_COMMANDS_H

#include <string>
#include <vector>

namespace ohmdem::post::cli {

struct Command {
  const char *name;
  const char *summary;
  int (*run)(const std::vector<std::string> &args);  // args after the command name
};

const std::vector<Command> &commands();

// Runs argv[1] with the rest; prints "ERROR: ..." and returns 1 on any error.
int dispatch(int argc, char **argv);

int run_stats(const std::vector<std::string> &args);
int run_spectrum(const std::vector<std::string> &args);
int run_envelope(const std::vector<std::string> &args);
int run_frequencies(const std::vector<std::string> &args);
int run_diagnose(const std::vector<std::string> &args);
int run_plot(const std::vector<std::string> &args);
int run_collect(const std::vector<std::string> &args);
int run_acquire(const std::vector<std::string> &args);
int run_orders(const std::vector<std::string> &args);
int run_size(const std::vector<std::string> &args);

}  // namespace ohmdem::post::cli

#endif
