// SPDX-License-Identifier: GPL-2.0-or-later
// Conjugate gradients preconditioned by algebraic multigrid (hypre's BoomerAMG), for the
// large network solves: CG with a diagonal preconditioner needs iterations in proportion to
// the network's diameter (time ~ N^1.35 on 3D packings), one AMG V-cycle per iteration keeps
// the iteration count nearly constant, so the time grows close to linearly.
// Plain C++ (no LIGGGHTS or Eigen types); every process solves its own copy of the network
// (MPI_COMM_SELF), so the result does not depend on the number of processes.
#ifndef OHMDEM_MULTIGRID_CG_H
#define OHMDEM_MULTIGRID_CG_H

namespace ohmdem {

struct MultigridResult {
  bool converged = false;
  int iterations = 0;              // CG iterations (one V-cycle each)
  double relative_residual = 0.0;  // ||b - A x||_2 / ||b||_2 at exit
};

// Solves A x = b for a symmetric positive definite A given in compressed rows (0-based,
// every row with its diagonal; a symmetric matrix in compressed columns is the same arrays).
// x holds the starting guess on entry (a warm start) and the solution on exit. Stops when
// ||b - A x||_2 <= tol ||b||_2 or after max_iterations. Starts MPI if the caller has not.
MultigridResult multigrid_cg(int n, const int *row_start, const int *columns, const double *values,
                             const double *b, double *x, double tol, int max_iterations);

}  // namespace ohmdem

#endif
