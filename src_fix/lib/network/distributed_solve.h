// SPDX-License-Identifier: GPL-2.0-or-later
// The resistance of a conduction network spread over the ranks of an MPI communicator:
// each rank gives the nodes it owns and its share of the conductances
// (distributed_system.h), the system is a hypre ParCSR matrix on that communicator, solved by
// CG preconditioned with BoomerAMG; no rank holds the whole network. The electrodes are
// Dirichlet nodes (high at 1 V, low at 0 V): G is the power of the solution (the current
// corrected by the residual, an error quadratic in the solution's error), R = 1 / G, and the
// potentials are scaled to the given current. Plain C++ with MPI, no LIGGGHTS types.
//
// CG stops on its own estimate of the error of R (energy_cg.h), not on a tiny
// residual: R to ~energy_tolerance relative with a third of the iterations.
//
// Reuse: while the sparsity pattern (the rows of every rank and their columns) is the same,
// the new values go into the same hypre matrix, and the multigrid hierarchy of the last setup
// is kept while the matrix moved by at most reuse_tolerance from the one of that setup
// (Frobenius norm, relative); otherwise it is set up again. CG with a kept hierarchy is exact
// CG on the new matrix with a fixed (older) preconditioner: only the iteration count can
// change, not the answer's accuracy.
//
// Deterministic: for a fixed number of ranks the same input gives the same bits (sorted
// assembly, hypre on one thread, sums in rank order). Different rank counts agree to the
// solver tolerance.
#ifndef OHMDEM_DISTRIBUTED_SOLVE_H
#define OHMDEM_DISTRIBUTED_SOLVE_H

#include <mpi.h>

#include <cstddef>
#include <memory>
#include <vector>

#include "network/distributed_system.h"

namespace ohmdem {

struct DistributedOptions {
  // CG stops at ||b - A x||_2 <= tolerance ||b||_2, or once a step lowers the power (G at 1 V)
  // by at most energy_tolerance of it: R is then accurate to ~energy_tolerance relative.
  double tolerance = 1e-12;
  double energy_tolerance = 1e-12;
  int max_iterations = 1000;
  bool reuse_setup = true;
  double reuse_tolerance = 0.1;  // ||A - A_setup||_F / ||A_setup||_F that still keeps it
  bool warm_start = true;        // CG starts from the last potentials of the same keys
};

struct DistributedSolution {
  double resistance = 0;  // ohm; +inf when no path joins the electrodes
  bool connected = false;
  bool converged = true;
  int iterations = 0;
  double relative_residual = 0;
  long long unknowns = 0;        // rows, over all ranks (floating ones included)
  long long floating_nodes = 0;  // rows of components that reach no electrode
  long long edges = 0;           // accepted conductances, over all ranks
  bool setup_reused = false;     // this solve kept the AMG hierarchy of an earlier one
  long long setups = 0;          // AMG setups since construction
};

class DistributedNetworkSolver {
 public:
  explicit DistributedNetworkSolver(MPI_Comm comm);
  ~DistributedNetworkSolver();
  DistributedNetworkSolver(const DistributedNetworkSolver &) = delete;
  DistributedNetworkSolver &operator=(const DistributedNetworkSolver &) = delete;

  void set_options(const DistributedOptions &o);
  const DistributedOptions &options() const;
  // Collective. `owned`: this rank's nodes; `edges`: this rank's share, each edge on one rank.
  // Throws std::invalid_argument for a current that is zero or not finite.
  DistributedSolution solve(const std::vector<NodeKey> &owned,
                            const std::vector<DistributedEdge> &edges, NodeKey high, NodeKey low,
                            double current);
  // After solve(): the potential (V) of a node this rank owns; 0 if floating or not owned.
  double potential(NodeKey key) const;
  // Collective: the potentials of any nodes (the electrodes too), owned anywhere.
  std::vector<double> potentials(const std::vector<NodeKey> &keys) const;
  // Bytes held by this rank (system, hypre matrices and hierarchy estimated from the entries).
  std::size_t memory_bytes() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ohmdem

#endif
