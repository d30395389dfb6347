// SPDX-License-Identifier: GPL-2.0-or-later
// Conjugate gradients on hypre's ParCSR objects, preconditioned by one BoomerAMG V-cycle per
// iteration, that stops when the power of a grounded Kirchhoff system (hence R) is accurate,
// not when the residual is tiny. Used by the distributed network solve (distributed_solve.h);
// plain C++ with MPI and hypre, no LIGGGHTS types.
//
// The system A x = b is the grounded Laplacian with the high electrode at 1 V eliminated into
// b; the power at x is P(x) = x'Ax - 2b'x + c (c = sum of b over all ranks). P(x) - P* =
// ||x - x*||_A^2, and each CG step lowers P by alpha * (r, z), so the error of P at a step is
// the sum of the decreases still to come (Hestenes and Stiefel's estimate). CG stops when that
// sum, extrapolated as a geometric series at the slowest ratio of the last three decreases, is
// at most energy_tolerance * P, or when ||r|| <= tolerance ||b||: R is then accurate to about
// energy_tolerance relative, the potentials to about its square root. Inner products are
// summed over the ranks in rank order: bitwise repeatable for a fixed number of ranks.
#ifndef OHMDEM_ENERGY_CG_H
#define OHMDEM_ENERGY_CG_H

#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

namespace ohmdem {

struct EnergyCgVectors {
  HYPRE_ParVector b, x;        // right-hand side; start guess in, solution out
  HYPRE_ParVector r, z, p, q;  // work: residual, preconditioned residual, direction, product
};

struct EnergyCgOptions {
  double tolerance;         // ||b - A x||_2 <= tolerance ||b||_2
  double energy_tolerance;  // estimated error of P <= energy_tolerance * P
  int max_iterations;
};

struct EnergyCgResult {
  int iterations = 0;
  bool converged = true;
  double relative_residual = 0;
};

// Collective. n: this rank's rows; rhs_sum: the sum of this rank's entries of b; amg: a
// hierarchy set up on A or on a matrix of the same pattern.
EnergyCgResult energy_cg(MPI_Comm comm, HYPRE_ParCSRMatrix A, HYPRE_Solver amg,
                         const EnergyCgVectors &v, int n, double rhs_sum, const EnergyCgOptions &o);

// This rank's entries of a hypre vector.
double *local_data(HYPRE_ParVector v);

}  // namespace ohmdem

#endif
