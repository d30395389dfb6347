// SPDX-License-Identifier: GPL-2.0-or-later
// The world's log file, known on every process.
//
// LIGGGHTS opens a world's log on its process 0 only (the -log file, then each `log` command),
// and an error raised on one process (Error::one) writes to that process's screen stream: with
// -screen none, or on another process, the message never reached the log. The executable
// defines Input::log itself, as it does the error exits (app/liggghts_errors.cpp): libliggghts
// calls it through the PLT; it runs LIGGGHTS' own (dlsym(RTLD_NEXT)) and then tells every
// process of the world where the log is now, so that Error::one can append its line to it.
#include <dlfcn.h>
#include <mpi.h>
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "input.h"
#include "lammps.h"
#include "run_status.h"

using namespace LAMMPS_NS;

void Input::log()
{
  using Original = void (*)(Input *);
  static const auto original =
      reinterpret_cast<Original>(dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS5Input3logEv"));
  if (!original) {
    std::fprintf(stderr, "ohmdem: cannot find Input::log in libliggghts (%s)\n", dlerror());
    std::abort();
  }
  original(this);
  ohmdem::learn_log_path(lmp);  // every process runs the command: collective
}
