// SPDX-License-Identifier: GPL-2.0-or-later
// hypre's run-time environment; see hypre_env.h.
#include "network/hypre_env.h"

#include <HYPRE.h>
#include <HYPRE_utilities.h>
#include <mpi.h>
#include <omp.h>

#include <cstdlib>

namespace ohmdem {

void ensure_hypre_started()
{
  int started = 0;
  MPI_Initialized(&started);
  if (!started) {  // a plain C++ caller (a test, a benchmark): hypre needs MPI
    MPI_Init(nullptr, nullptr);
    std::atexit([] {
      int finished = 0;
      MPI_Finalized(&finished);
      if (!finished) MPI_Finalize();
    });
  }
  static const bool ready = [] {
    HYPRE_Init();
    return true;
  }();
  (void)ready;
}

HypreOneThread::HypreOneThread() : threads_(omp_get_max_threads())
{
  omp_set_num_threads(1);
}

HypreOneThread::~HypreOneThread()
{
  omp_set_num_threads(threads_);
}

}  // namespace ohmdem
