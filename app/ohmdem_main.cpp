// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem: the LIGGGHTS engine with the ohmdem styles.
//
// Identical to LIGGGHTS' own main(): same command line (-in, -var, -log, -screen, -echo,
// -partition, -help, ...), same signal handling. Our styles are registered by the start-up
// hook in ohmdem_styles.cpp, which LIGGGHTS calls on creation and after every `clear`.
// Unlike LIGGGHTS, a run stopped by SIGINT/SIGTERM exits with status 3, and a run that did
// not finish says so in its run.json (run_status.h, doc/run_status.md).
#include <mpi.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "comm.h"
#include "input.h"
#include "lammps.h"
#include "run_status.h"
#include "signal_handling.h"
#include "variable.h"

using LAMMPS_NS::LAMMPS;
namespace SignalHandler = LAMMPS_NS::SignalHandler;

namespace ohmdem {
const char *version();  // app/ohmdem_version.cpp
}

namespace {

// The log file takes what was written to it so far (a full disk, -log /dev/full: LIGGGHTS
// never checks): 0, or the error of the failed write, on every process of the world.
int log_write_error(LAMMPS &lammps, const char *what)
{
  int err = 0;
  if (lammps.comm->me == 0 && lammps.logfile) {
    errno = 0;
    if (std::fflush(lammps.logfile) != 0 || std::ferror(lammps.logfile)) err = errno ? errno : EIO;
  }
  MPI_Bcast(&err, 1, MPI_INT, 0, lammps.world);
  if (err && lammps.comm->me == 0) {
    const std::string msg = std::string("ERROR: the log file cannot be written: ") +
                            std::strerror(err) + " (" + what + ")\n";
    std::fputs(msg.c_str(), stderr);
    if (lammps.screen && lammps.screen != stdout && lammps.screen != stderr)
      std::fputs(msg.c_str(), lammps.screen);
  }
  return err;
}

// The same -var NAME given twice: LIGGGHTS keeps the first value and drops the second without
// a word (a case table's column and a launcher's default, a script's -var and the user's).
// LIGGGHTS' own reading of -var: NAME, a first value, then more values up to the next word
// starting with '-'.
void warn_repeated_variables(LAMMPS &lammps, int argc, char **argv)
{
  if (lammps.comm->me != 0) return;
  std::map<std::string, std::string> first;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "-var") != 0 && std::strcmp(argv[i], "-v") != 0) continue;
    if (i + 2 >= argc) break;
    const std::string name = argv[i + 1], value = argv[i + 2];
    const auto [it, fresh] = first.emplace(name, value);
    if (!fresh) {
      const std::string msg = "WARNING: -var " + name + " given twice: the first value ('" +
                              it->second + "') is used, the second ('" + value +
                              "') is ignored (LIGGGHTS keeps the first)\n";
      for (FILE *f : {lammps.screen, lammps.logfile})
        if (f) std::fputs(msg.c_str(), f);
    }
    i += 2;
    while (i + 1 < argc && argv[i + 1][0] != '-') ++i;
  }
}

}  // namespace

int main(int argc, char **argv)
{
  // --version: ours and the engine's, before MPI (LIGGGHTS refuses the flag).
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("ohmdem %s (on LIGGGHTS 3.8: its version is the first line of a run's log)\n",
                ohmdem::version());
    return 0;
  }
  // Line-buffered screen output: an error written just before an abort reaches a redirected
  // stdout (see also MPI_Abort in run_status.cpp).
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  // SIGTERM as SIGINT: Open MPI turns a SIGINT to mpirun into SIGTERM for its children.
  struct sigaction int_action;
  struct sigaction usr1_action;
  std::memset(&int_action, 0, sizeof(int_action));
  std::memset(&usr1_action, 0, sizeof(usr1_action));
  int_action.sa_handler = SignalHandler::int_handler;
  sigaction(SIGINT, &int_action, nullptr);
  sigaction(SIGTERM, &int_action, nullptr);
  usr1_action.sa_handler = SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);

  MPI_Init(&argc, &argv);
  ohmdem::RunEnd end = ohmdem::RunEnd::Finished;
  bool log_lost = false;
  {
    LAMMPS lammps(argc, argv, MPI_COMM_WORLD);
    ohmdem::record_failure_at_exit(&lammps);
    ohmdem::learn_log_path(&lammps);
    warn_repeated_variables(lammps, argc, argv);
    // The version in the log and as the deck variable ohmdem_version (run.json records it).
    {
      std::string words[3] = {"ohmdem_version", "string", ohmdem::version()};
      char *set[3] = {words[0].data(), words[1].data(), words[2].data()};
      lammps.input->variable->set(3, set);
      if (lammps.comm->me == 0) {
        if (lammps.screen) std::fprintf(lammps.screen, "ohmdem %s\n", ohmdem::version());
        if (lammps.logfile) std::fprintf(lammps.logfile, "ohmdem %s\n", ohmdem::version());
      }
    }
    // A log that cannot be written stops the run before it starts; one that fills during the
    // run makes the exit status 1 (doc/run_status.md).
    if (log_write_error(lammps, "the deck is not run") == 0) {
      lammps.input->file();
      if (SignalHandler::request_quit) end = ohmdem::RunEnd::Interrupted;
      ohmdem::record_unfinished_run(&lammps, end);
      if (log_write_error(lammps, "the log is incomplete") != 0) log_lost = true;
    } else {
      log_lost = true;
    }
    ohmdem::disarm_failure_at_exit();
  }
  MPI_Finalize();
  const int status = ohmdem::exit_status(end);
  return status == 0 && log_lost ? 1 : status;
}
