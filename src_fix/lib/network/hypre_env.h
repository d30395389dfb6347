// SPDX-License-Identifier: GPL-2.0-or-later
// hypre's run-time environment for the network solvers (multigrid_cg, distributed_solve):
// MPI and hypre started once, and hypre's OpenMP loops held to one thread while a solve runs.
#ifndef OHMDEM_HYPRE_ENV_H
#define OHMDEM_HYPRE_ENV_H

namespace ohmdem {

// Starts MPI if the caller has not (a plain C++ test or benchmark), then hypre, once.
void ensure_hypre_started();

// hypre's OpenMP loops on one thread: their reductions would otherwise add in an order that
// depends on the thread count (set by the machine and by MPI's core binding), so the last
// bits of R could change from one launch to another. Measured: no loss of speed on these
// networks (the same times with OMP_NUM_THREADS=1 and 2).
class HypreOneThread {
 public:
  HypreOneThread();
  ~HypreOneThread();
  HypreOneThread(const HypreOneThread &) = delete;
  HypreOneThread &operator=(const HypreOneThread &) = delete;

 private:
  int threads_;
};

}  // namespace ohmdem

#endif
