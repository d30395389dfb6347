// SPDX-License-Identifier: GPL-2.0-or-later
// The solve strategy of a conduction network (internal to network/): the grounded, diagonally
// scaled Laplacian of the reduced graph solved by CG (diagonal, incomplete Cholesky or
// multigrid preconditioner, warm-started), else by sparse LDL^T with iterative refinement,
// else by the exact Kron elimination. Why each step: doc/methods/conduction_network.md.
#ifndef OHMDEM_NETWORK_SOLVE_H
#define OHMDEM_NETWORK_SOLVE_H

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

#include "network/network_graph.h"

namespace ohmdem::net {

using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vec = Eigen::VectorXd;

// The reduced graph to solve: its nodes with an unknown (unk[i] >= 0, m of them), the
// electrodes (current in at ih, il grounded), and the node keys for the warm start.
struct ReducedSystem {
  const Adjacency &adj;
  const std::vector<int> &unk;
  int ih, il;
  double current;
  const std::vector<NodeKey> &keys;
};

// Potentials per unit current of the last connected solve, sorted by key.
struct WarmStart {
  std::vector<NodeKey> keys;
  std::vector<double> values;
};

class SystemSolver {
 public:
  // Fills s.resistance, s.method, s.iterations, s.relative_residual (s.unknowns is set) and
  // the potentials v[i] of the nodes with an unknown and of the electrodes.
  void solve(const ReducedSystem &sys, SolverKind kind, const SolverOptions &opt,
             const WarmStart &warm, std::vector<double> &v, NetworkSolution &s);

 private:
  struct Ldlt : Eigen::SimplicialLDLT<SpMat> {
    // Multiply-adds of the numeric factorization, sum of squared column counts of L, known
    // after analyzePattern() (Eigen keeps the counts in a protected member).
    double flops() const;
  };
  class Run;
  // The symbolic analysis is reused while the sparsity pattern is unchanged.
  void analyze(const SpMat &A);
  SolverKind choose(const SpMat &A, SolverKind kind, const SolverOptions &opt);

  Ldlt ldlt_;
  std::vector<int> pattern_outer_, pattern_inner_;
};

}  // namespace ohmdem::net

#endif
