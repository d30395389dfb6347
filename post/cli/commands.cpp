// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/commands.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

#include "cli/common.h"
#include "cli/setting_flags.h"
#include "core/error.h"

namespace ohmdem {
const char *version();
}

namespace ohmdem::post::cli {

const std::vector<Command> &commands()
{
  static const std::vector<Command> table = {
      {"stats", "statistical indicators (peak, RMS, crest, kurtosis, ...), optionally per window",
       run_stats},
      {"spectrum",
       "one-sided amplitude/power/PSD spectrum (window, detrend, padding, Welch), peaks",
       run_spectrum},
      {"envelope", "band-pass + Hilbert envelope and its spectrum; kurtogram to choose the band",
       run_envelope},
      {"frequencies", "kinematic defect frequencies (FTF, BPFO, BPFI, BSF) of a bearing",
       run_frequencies},
      {"diagnose", "most likely defect (inner/outer/ball/cage/none), score, evidence, size",
       run_diagnose},
      {"size", "a race defect's size and place, each within its method's measured validity",
       run_size},
      {"plot", "PNG figures with gnuplot: signal, spectrum with defect frequencies, indicators",
       run_plot},
      {"collect", "the indicators (and parameters, diagnosis) of many run folders in one table",
       run_collect},
      {"acquire", "what an instrument records: sensitivity, anti-alias filter, rate, noise, ADC",
       run_acquire},
      {"orders", "order tracking: (envelope) order spectrum at constant shaft-angle increments",
       run_orders},
  };
  return table;
}

namespace {

void usage(std::ostream &out)
{
  out << "ohmdem-post " << ohmdem::version()
      << ": post-processing of bearing signals (ohmdem, LIGGGHTS outputs, measured records)\n\n"
         "usage: ohmdem-post <command> [options] FILE...\n\ncommands:\n";
  for (const auto &c : commands()) {
    std::string n = c.name;
    n.resize(13, ' ');
    out << "  " << n << c.summary << "\n";
  }
  out << "\n'ohmdem-post <command> --help' (or 'ohmdem-post help <command>') describes a "
         "command's options.\n";
}

}  // namespace

namespace {

int dispatch_command(int argc, char **argv);

// Standard output flushed and checked (a full disk, a closed pipe, /dev/full): a lost output
// is an error, never exit 0 with nothing written. Then the files of --output.
int checked_exit(int status)
{
  std::cout.flush();
  const bool out_ok = std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (!out_ok) {
    std::cerr << "ERROR: writing standard output failed (" << std::strerror(errno)
              << "): the output is lost or cut\n";
    return 1;
  }
  if (!failed_outputs().empty()) {
    for (const auto &f : failed_outputs()) std::cerr << "ERROR: " << f << "\n";
    return 1;
  }
  return status;
}

}  // namespace

int dispatch(int argc, char **argv)
{
  warning_sink() = [](const std::string &m) { std::cerr << "WARNING: " << m << "\n"; };
  const int status = dispatch_command(argc, argv);
  return checked_exit(status);
}

namespace {

int dispatch_command(int argc, char **argv)
{
  if (argc < 2) {
    usage(std::cerr);
    std::cerr << "ERROR: no command given\n";
    return 2;
  }
  std::string name = argv[1];
  // help COMMAND: as COMMAND --help
  std::vector<std::string> rest(argv + 2, argv + argc);
  if (name == "help" && argc == 3) {
    name = argv[2];
    rest = {"--help"};
  }
  if (name == "--help" || name == "-h" || name == "help") {
    usage(std::cout);
    return 0;
  }
  if (name == "--version") {
    std::cout << "ohmdem-post " << ohmdem::version() << "\n";
    return 0;
  }
  for (const auto &c : commands()) {
    if (name != c.name) continue;
    try {
      return c.run(rest);
    } catch (const Error &e) {
      std::cerr << "ERROR: " << user_message(e) << "\n";
    } catch (const std::bad_alloc &) {
      std::cerr << "ERROR: out of memory\n";
    } catch (const std::exception &e) {
      std::cerr << "ERROR: " << c.name << ": " << e.what() << "\n";
    }
    return 1;
  }
  std::cerr << "ERROR: unknown command '" << name << "' (commands:";
  for (const auto &c : commands()) std::cerr << " " << c.name;
  std::cerr << "; see ohmdem-post --help)\n";
  return 2;
}

}  // namespace

}  // namespace ohmdem::post::cli
