// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem: the LIGGGHTS engine with the ohmdem styles.
//
// Identical to LIGGGHTS' own main(): same command line (-in, -var, -log, -screen, -echo,
// -partition, -help, ...), same signal handling. Our styles are registered by the start-up
// hook in ohmdem_styles.cpp, which LIGGGHTS calls on creation and after every `clear`.
// Unlike LIGGGHTS, a run stopped by SIGINT/SIGTERM exits with status 3, and a run that did
// not finish says so in its run.json (run_status.h, doc/run_status.md).
#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <cstring>
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
  {
    LAMMPS lammps(argc, argv, MPI_COMM_WORLD);
    ohmdem::record_failure_at_exit(&lammps);
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
    lammps.input->file();
    if (SignalHandler::request_quit) end = ohmdem::RunEnd::Interrupted;
    ohmdem::record_unfinished_run(&lammps, end);
    ohmdem::disarm_failure_at_exit();
  }
  MPI_Finalize();
  return ohmdem::exit_status(end);
}
