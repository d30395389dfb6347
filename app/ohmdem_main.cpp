// ohmdem: the LIGGGHTS engine with the ohmdem styles.
//
// Identical to LIGGGHTS' own main(): same command line (-in, -var, -log, -screen, -echo,
// -partition, -help, ...), same signal handling. Our styles are registered by the start-up
// hook in ohmdem_styles.cpp, which LIGGGHTS calls on creation and after every `clear`.
#include <mpi.h>

#include <csignal>
#include <cstring>

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

using LAMMPS_NS::LAMMPS;
namespace SignalHandler = LAMMPS_NS::SignalHandler;

int main(int argc, char **argv)
{
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
  {
    LAMMPS lammps(argc, argv, MPI_COMM_WORLD);
    lammps.input->file();
  }
  MPI_Finalize();
  return 0;
}
