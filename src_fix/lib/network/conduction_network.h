// SPDX-License-Identifier: GPL-2.0-or-later
// Electrical network of a contact network: Kirchhoff + Ohm on a graph whose nodes are
// contact points and whose edges are conductances (paper eq. 1 inside particles, optionally
// Holm constriction conductances across contacts). Two nodes are electrodes: current I
// enters `high`, `low` is at 0 V, and R = V_high / I.
//
// Plain C++ (no LIGGGHTS types). Eigen is hidden behind a PIMPL so that including this
// header stays cheap. Physics and numerics: doc/methods/conduction_network.md.
//
// Determinism: the result depends only on the multiset of (a, b, g) added, never on the
// insertion order (edges are sorted canonically before anything is summed), so contacts
// gathered from MPI ranks in rank order give bitwise identical R for any process count.
#ifndef OHMDEM_CONDUCTION_NETWORK_H
#define OHMDEM_CONDUCTION_NETWORK_H

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace ohmdem {

// Caller-chosen stable node ids (e.g. built from particle tags, see contact_key()), never
// insertion indices: they carry warm-start potentials from one solve to the next.
using NodeKey = std::uint64_t;

// A suggested key scheme. Particle tags start at 1, so contact keys are >= 2^32 and keys
// below 2^32 are free for electrodes (electrode_key).
constexpr NodeKey electrode_key(std::uint32_t id)
{
  return id;
}
// Key of the single node of a contact between particles with tags ta and tb (symmetric).
constexpr NodeKey contact_key(std::uint32_t ta, std::uint32_t tb)
{
  return ta < tb ? (NodeKey(ta) << 32) | tb : (NodeKey(tb) << 32) | ta;
}
// Key of the side of that contact that belongs to particle `owner` (asymmetric). Used when
// a contact is split into two nodes joined by a series (Holm) conductance.
constexpr NodeKey contact_side_key(std::uint32_t owner, std::uint32_t other)
{
  return (NodeKey(owner) << 32) | other;
}

enum class SolverKind { Auto, Direct, ConjugateGradient };
// Elimination: the exact (subtraction-free) Kron elimination, the fallback when a direct
// LDL^T cannot reach its accuracy (conductances spread over ~16 decades or more).
enum class SolveMethod { None, ClosedForm, Direct, ConjugateGradient, MultigridCG, Elimination };
// Multigrid: hypre's BoomerAMG, one V-cycle per CG iteration (multigrid_cg.h): iterations
// nearly independent of the network size, for large networks.
enum class Preconditioner { Diagonal, IncompleteCholesky, Multigrid };
// "none", "closed-form", "direct", "cg", "cg-amg", "elimination"
const char *to_string(SolveMethod m);

struct SolverOptions {
  SolverKind kind = SolverKind::Auto;
  // Auto (deterministic: from the sparsity pattern only). Direct (sparse LDL^T) up to
  // auto_direct_unknowns unknowns, CG above auto_cg_unknowns; in between, direct if the
  // symbolic analysis predicts at most auto_flops_per_nonzero multiply-adds per nonzero of
  // the matrix (measured crossover: ~250-500, i.e. the cost of a few hundred CG iterations;
  // 2D packings stay direct up to ~1e5 unknowns, 3D ones switch to CG near 2e3).
  // When Auto picks CG for at least auto_multigrid_unknowns unknowns, its preconditioner is
  // algebraic multigrid: its iterations hardly grow with the size (3D packings, 883 -> 286k
  // unknowns: 11 -> 26, diagonal 55 -> 348), but each costs ~5x more; per step it was still
  // 15 % slower at 286k, and the measured growths (N^1.12 against N^1.23) cross near 1e6.
  int auto_direct_unknowns = 2000;
  int auto_cg_unknowns = 500000;
  double auto_flops_per_nonzero = 500;
  int auto_multigrid_unknowns = 1000000;
  // CG stopping test on the diagonally scaled system: ||b - A y|| <= tol * ||b||. R comes
  // from the energy functional, whose error is quadratic in the solution error: 1e-8 gives
  // R to ~1e-14 on the benchmarks (potentials and currents to ~tol).
  double cg_tolerance = 1e-8;
  int cg_max_iterations = 0;  // 0: max(1000, 2 * unknowns); no convergence -> direct solve
  // Diagonal: CG on the symmetrically scaled system (Jacobi). Incomplete Cholesky halves the
  // iterations but costs more than it saves with Eigen's implementation (bench/). Multigrid
  // (hypre BoomerAMG) needs 10-20x fewer iterations, each ~5x dearer, plus a setup per solve.
  Preconditioner preconditioner = Preconditioner::Diagonal;
  bool warm_start = true;     // CG starts from the last solve's potentials (per unit I)
  bool reduce_series = true;  // exact elimination of dangling and degree-2 nodes
};

struct NetworkSolution {
  double resistance = 0;    // ohm; +inf if the electrodes are not connected
  double current = 0;       // A, as given
  double voltage_drop = 0;  // V, = resistance * current (+inf if not connected)
  bool connected = false;
  SolveMethod method = SolveMethod::None;
  int conducting_edges = 0;        // added conductances in the solved component
  int floating_nodes_dropped = 0;  // nodes outside the component holding both electrodes
  int eliminated_nodes = 0;        // dangling + series nodes removed before the solve
  int unknowns = 0;                // size of the linear system (0 for a closed form)
  int ignored_conductances = 0;    // g <= 0 or non-finite, since clear()
  int self_loops = 0;              // a == b (e.g. two contacts on the same electrode)
  int iterations = 0;              // CG iterations (direct: refinement steps)
  double relative_residual = 0;    // ||b - L v||_2 / |I|, UNSCALED grounded system (by edge)
};

// One added conductance, as reported after a solve (canonical order: a < b, then g).
struct NetworkEdge {
  NodeKey a, b;
  double conductance;  // S
  double current;      // A, flowing from a to b: g * (V_a - V_b)
  bool connected;      // part of the solved component
};

struct NetworkNode {
  NodeKey key;
  double potential;  // V; 0 if floating
  bool connected;
};

class ConductionNetwork {
 public:
  ConductionNetwork();
  ~ConductionNetwork();
  ConductionNetwork(ConductionNetwork &&) noexcept;
  ConductionNetwork &operator=(ConductionNetwork &&) noexcept;
  ConductionNetwork(const ConductionNetwork &) = delete;
  ConductionNetwork &operator=(const ConductionNetwork &) = delete;

  // Drops edges, counters and the last solution; keeps the electrodes, the options and the
  // warm-start potentials (stored by NodeKey).
  void clear();
  // Also forgets the warm-start potentials.
  void reset();
  void reserve(std::size_t edges);

  // Parallel edges add up, so a contact seen on two MPI ranks (newton off) must be added
  // once. g <= 0 or non-finite is ignored (counted), a == b is ignored (counted): a contact
  // between two parts of one electrode carries no current.
  void add_conductance(NodeKey a, NodeKey b, double g);
  void set_electrodes(NodeKey high, NodeKey low);
  void set_options(const SolverOptions &options);
  const SolverOptions &options() const;

  // Throws std::invalid_argument if the electrodes were never set or the current is zero or
  // not finite (caller bugs). A missing path is not an error: resistance = +inf.
  NetworkSolution solve(double current);
  NetworkSolution solve(double current, SolverKind kind);

  // After solve(): potential of a node (V); 0 for floating or unknown keys.
  double potential(NodeKey key) const;
  bool is_connected(NodeKey key) const;
  const NetworkSolution &last_solution() const;

  NodeKey high() const;
  NodeKey low() const;
  bool has_electrodes() const;
  std::size_t num_edges() const;  // accepted conductances
  // Canonically ordered views for the exporters (currents/potentials from the last solve,
  // zero if the network changed since). They sort lazily (cached): not for concurrent calls.
  std::vector<NetworkEdge> edges() const;
  std::vector<NetworkNode> nodes() const;
  // The accepted conductances as added (no sorting, no solve state; current 0): for a caller
  // that only collects a network, such as the distributed path.
  template <class F>
  void for_each_added(F &&f) const
  {
    for (std::size_t k = 0, n = num_edges(); k < n; ++k) {
      const NetworkEdge e = added_edge(k);
      f(e.a, e.b, e.conductance);
    }
  }
  NetworkEdge added_edge(std::size_t k) const;  // current 0

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ohmdem

#endif
