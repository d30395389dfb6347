// SPDX-License-Identifier: GPL-2.0-or-later
// The distributed network solve: hypre IJ/ParCSR, CG + BoomerAMG; see distributed_solve.h.
#include "network/distributed_solve.h"

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>

#include "network/energy_cg.h"
#include "network/hypre_env.h"
#include "network/key_directory.h"

namespace ohmdem {

static_assert(std::is_same<HYPRE_Int, int>::value && std::is_same<HYPRE_BigInt, int>::value,
              "built for hypre with 32-bit indices (Debian's libhypre-dev)");

namespace {

struct IJMatrix {
  HYPRE_IJMatrix h = nullptr;
  ~IJMatrix() { reset(); }
  void reset()
  {
    if (h) HYPRE_IJMatrixDestroy(h);
    h = nullptr;
  }
};
struct IJVector {
  HYPRE_IJVector h = nullptr;
  ~IJVector() { reset(); }
  void reset()
  {
    if (h) HYPRE_IJVectorDestroy(h);
    h = nullptr;
  }
};

// A new matrix (fresh = true) or new values in the entries of an assembled one of the same
// pattern (hypre sets the existing entries in place: no second matrix is held).
void set_matrix(MPI_Comm comm, const DistributedSystem &s, IJMatrix &m, bool fresh)
{
  const int n = static_cast<int>(s.keys.size());
  const int lo = s.first_row, hi = s.first_row + n - 1;
  std::vector<int> rows(n), sizes(n);
  std::iota(rows.begin(), rows.end(), lo);
  for (int i = 0; i < n; ++i) sizes[i] = s.row_start[i + 1] - s.row_start[i];
  if (fresh) {
    m.reset();
    HYPRE_IJMatrixCreate(comm, lo, hi, lo, hi, &m.h);
    HYPRE_IJMatrixSetObjectType(m.h, HYPRE_PARCSR);
    if (n) HYPRE_IJMatrixSetRowSizes(m.h, sizes.data());
    HYPRE_IJMatrixInitialize(m.h);
  }
  if (n)
    HYPRE_IJMatrixSetValues(m.h, n, sizes.data(), rows.data(), s.columns.data(), s.values.data());
  if (fresh) HYPRE_IJMatrixAssemble(m.h);
}

// Collective: a vector of zeros over this rank's rows [first, first + n).
void make_vector(MPI_Comm comm, int first, int n, IJVector &out)
{
  out.reset();
  const std::vector<double> zero(n, 0.0);
  std::vector<int> rows(n);
  std::iota(rows.begin(), rows.end(), first);
  HYPRE_IJVectorCreate(comm, first, first + n - 1, &out.h);
  HYPRE_IJVectorSetObjectType(out.h, HYPRE_PARCSR);
  HYPRE_IJVectorInitialize(out.h);
  if (n) HYPRE_IJVectorSetValues(out.h, n, rows.data(), zero.data());
  HYPRE_IJVectorAssemble(out.h);
}

HYPRE_ParVector par(const IJVector &v)
{
  HYPRE_ParVector p;
  HYPRE_IJVectorGetObject(v.h, reinterpret_cast<void **>(&p));
  return p;
}

}  // namespace

class DistributedNetworkSolver::Impl {
 public:
  explicit Impl(MPI_Comm comm) : comm_(comm) {}
  ~Impl() { drop_setup(); }

  DistributedSolution solve(const std::vector<NodeKey> &owned,
                            const std::vector<DistributedEdge> &edges, NodeKey high, NodeKey low,
                            double current);
  void drop_setup()
  {
    if (amg_) HYPRE_BoomerAMGDestroy(amg_);
    amg_ = nullptr;
  }
  bool same_pattern() const;
  bool setup_still_good() const;
  void new_setup(HYPRE_ParCSRMatrix pA, HYPRE_ParVector pb, HYPRE_ParVector px);
  std::vector<double> start_guess() const;
  void ensure_vectors();
  double power(const std::vector<double> &x) const;

  MPI_Comm comm_;
  DistributedOptions opt_;
  DistributedSystem sys_;
  // CG's vectors (right-hand side, solution, residual, preconditioned residual, direction,
  // product), kept while this rank's rows stay the same.
  IJVector b_, x_vec_, r_, z_, p_, q_;
  int vectors_first_ = -1, vectors_rows_ = -1;
  std::vector<double> x_;           // potentials of sys_.keys (V) after the last solve
  std::vector<NodeKey> warm_keys_;  // keys and per-volt potentials of the last solve
  std::vector<double> warm_x_;
  // The matrix, kept from one solve to the next while its pattern stays (new values are set
  // in place), and the multigrid hierarchy set up on it.
  IJMatrix matrix_;
  HYPRE_Solver amg_ = nullptr;
  int matrix_first_ = -1;
  std::vector<int> matrix_start_, matrix_columns_;  // the pattern of matrix_
  std::vector<float> setup_values_;  // the values at the last setup (a 10 % test: floats do)
  long long setups_ = 0;
  NodeKey high_ = 0, low_ = 0;
  double v_high_ = 0.0;  // V of the high electrode after the last solve (0 without a path)
};

// The rows of every rank and their columns are those of the kept matrix.
bool DistributedNetworkSolver::Impl::same_pattern() const
{
  int same = matrix_.h && matrix_first_ == sys_.first_row && matrix_start_ == sys_.row_start &&
             matrix_columns_ == sys_.columns;
  MPI_Allreduce(MPI_IN_PLACE, &same, 1, MPI_INT, MPI_MIN, comm_);
  return same != 0;
}

// Kept while the pattern is the same on every rank and ||A - A_setup||_F <= tol ||A_setup||_F.
// (A bound on every entry would be stricter than needed: eq. 1 conductances of nearby spots
// move by tens of percent when the packing moves by 1 % of an overlap, and a few such edges
// only cost CG an iteration or two.) Called with the same pattern on every rank.
bool DistributedNetworkSolver::Impl::setup_still_good() const
{
  if (!amg_ || !opt_.reuse_setup) return false;
  double change = 0.0, size = 0.0;
  for (std::size_t k = 0; k < sys_.values.size(); ++k) {
    const double d = sys_.values[k] - setup_values_[k];
    change += d * d;
    size += static_cast<double>(setup_values_[k]) * setup_values_[k];
  }
  change = ordered_rank_sum(change, comm_);
  size = ordered_rank_sum(size, comm_);
  return change <= opt_.reuse_tolerance * opt_.reuse_tolerance * size;
}

// The same BoomerAMG settings as the serial multigrid CG (multigrid_cg.cpp, where they were
// measured): HMIS, extended+i interpolation truncated to 4, one level of aggressive coarsening,
// symmetric hybrid Gauss-Seidel, one V-cycle per CG iteration.
void DistributedNetworkSolver::Impl::new_setup(HYPRE_ParCSRMatrix pA, HYPRE_ParVector pb,
                                               HYPRE_ParVector px)
{
  drop_setup();
  HYPRE_BoomerAMGCreate(&amg_);
  HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
  HYPRE_BoomerAMGSetMaxIter(amg_, 1);
  HYPRE_BoomerAMGSetTol(amg_, 0.0);
  HYPRE_BoomerAMGSetCoarsenType(amg_, 10);
  HYPRE_BoomerAMGSetInterpType(amg_, 6);
  HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
  HYPRE_BoomerAMGSetAggNumLevels(amg_, 1);
  HYPRE_BoomerAMGSetStrongThreshold(amg_, 0.25);
  HYPRE_BoomerAMGSetRelaxType(amg_, 6);
  HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
  HYPRE_BoomerAMGSetup(amg_, pA, pb, px);
  setup_values_.assign(sys_.values.begin(), sys_.values.end());
  ++setups_;
}

// Collective: new vectors when some rank's rows moved (every rank creates them together).
void DistributedNetworkSolver::Impl::ensure_vectors()
{
  const int n = static_cast<int>(sys_.keys.size());
  int moved = vectors_first_ != sys_.first_row || vectors_rows_ != n;
  MPI_Allreduce(MPI_IN_PLACE, &moved, 1, MPI_INT, MPI_MAX, comm_);
  if (!moved) return;
  for (IJVector *v : {&b_, &x_vec_, &r_, &z_, &p_, &q_}) make_vector(comm_, sys_.first_row, n, *v);
  vectors_first_ = sys_.first_row;
  vectors_rows_ = n;
}

std::vector<double> DistributedNetworkSolver::Impl::start_guess() const
{
  std::vector<double> x0(sys_.keys.size(), 0.0);
  if (!opt_.warm_start) return x0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    auto it = std::lower_bound(warm_keys_.begin(), warm_keys_.end(), sys_.keys[i]);
    if (it != warm_keys_.end() && *it == sys_.keys[i] && !sys_.floating[i])
      x0[i] = warm_x_[it - warm_keys_.begin()];
  }
  return x0;
}

// The power at 1 V, sum of g (V_a - V_b)^2 over the edges: the minimum of the energy, so its
// error is quadratic in the potentials' error, and each term is a difference of potentials,
// never a sum of large terms that cancel (a matvec residual would lose ~ the conductance
// spread in digits: bulk and constriction conductances are decades apart).
double DistributedNetworkSolver::Impl::power(const std::vector<double> &x) const
{
  const std::vector<double> ghost = values_at_rows(comm_, sys_, x, sys_.ghosts);
  const int first = sys_.first_row, n = static_cast<int>(x.size());
  double mine = 0.0;
  for (int i = 0; i < n; ++i) {
    if (sys_.floating[i]) continue;
    const double v = x[i];
    double row = sys_.rhs[i] * (1.0 - v) * (1.0 - v) + sys_.to_low[i] * v * v;
    for (int k = sys_.row_start[i]; k < sys_.row_start[i + 1]; ++k) {
      const int c = sys_.columns[k];
      if (c == first + i) continue;
      const double w = c >= first && c < first + n
                           ? x[c - first]
                           : ghost[std::lower_bound(sys_.ghosts.begin(), sys_.ghosts.end(), c) -
                                   sys_.ghosts.begin()];
      // each edge between two rows is seen from both: half here
      row += 0.5 * (-sys_.values[k]) * (v - w) * (v - w);
    }
    mine += row;
  }
  return ordered_rank_sum(mine, comm_);
}

DistributedSolution DistributedNetworkSolver::Impl::solve(const std::vector<NodeKey> &owned,
                                                          const std::vector<DistributedEdge> &edges,
                                                          NodeKey high, NodeKey low, double current)
{
  if (!(current != 0.0) || !std::isfinite(current))
    throw std::invalid_argument("distributed network: the current must be finite and non-zero");
  ensure_hypre_started();
  const HypreOneThread one_thread;
  assemble_distributed(comm_, owned, edges, high, low, sys_);
  DistributedSolution out;
  out.unknowns = sys_.total_rows;
  out.floating_nodes = sys_.floating_rows;
  out.edges = sys_.edges;
  out.connected = sys_.connected;
  out.setups = setups_;
  const int n = static_cast<int>(sys_.keys.size());
  x_.assign(n, 0.0);
  if (!sys_.connected) {
    out.resistance = std::numeric_limits<double>::infinity();
    return out;
  }
  double conductance = sys_.direct;
  if (sys_.total_rows > sys_.floating_rows) {
    const bool same = same_pattern();
    if (!same) {
      drop_setup();
      matrix_first_ = sys_.first_row;
      matrix_start_ = sys_.row_start;
      matrix_columns_ = sys_.columns;
    }
    set_matrix(comm_, sys_, matrix_, !same);
    ensure_vectors();
    const HYPRE_ParVector pb = par(b_), px = par(x_vec_);
    std::copy(sys_.rhs.begin(), sys_.rhs.end(), local_data(pb));
    const std::vector<double> x0 = start_guess();
    std::copy(x0.begin(), x0.end(), local_data(px));
    HYPRE_ParCSRMatrix pA;
    HYPRE_IJMatrixGetObject(matrix_.h, reinterpret_cast<void **>(&pA));
    out.setup_reused = same && setup_still_good();
    if (!out.setup_reused) new_setup(pA, pb, px);
    out.setups = setups_;
    const EnergyCgResult cg = energy_cg(
        comm_, pA, amg_, {pb, px, par(r_), par(z_), par(p_), par(q_)}, n,
        std::accumulate(sys_.rhs.begin(), sys_.rhs.end(), 0.0),
        {opt_.tolerance, opt_.energy_tolerance, opt_.max_iterations});
    out.iterations = cg.iterations;
    out.converged = cg.converged;
    out.relative_residual = cg.relative_residual;
    x_.assign(local_data(px), local_data(px) + n);
    conductance += power(x_);
  }
  warm_keys_ = sys_.keys;
  warm_x_ = x_;
  out.resistance = conductance > 0.0 ? 1.0 / conductance : std::numeric_limits<double>::infinity();
  const double v_high = out.resistance * current;
  for (double &v : x_) v *= v_high;
  return out;
}

DistributedNetworkSolver::DistributedNetworkSolver(MPI_Comm comm)
    : impl_(std::make_unique<Impl>(comm))
{
}

DistributedNetworkSolver::~DistributedNetworkSolver() = default;

void DistributedNetworkSolver::set_options(const DistributedOptions &o)
{
  impl_->opt_ = o;
}

const DistributedOptions &DistributedNetworkSolver::options() const
{
  return impl_->opt_;
}

DistributedSolution DistributedNetworkSolver::solve(const std::vector<NodeKey> &owned,
                                                    const std::vector<DistributedEdge> &edges,
                                                    NodeKey high, NodeKey low, double current)
{
  impl_->high_ = high;
  impl_->low_ = low;
  impl_->v_high_ = 0.0;
  DistributedSolution s = impl_->solve(owned, edges, high, low, current);
  if (std::isfinite(s.resistance)) impl_->v_high_ = s.resistance * current;
  return s;
}

double DistributedNetworkSolver::potential(NodeKey key) const
{
  const auto &keys = impl_->sys_.keys;
  auto it = std::lower_bound(keys.begin(), keys.end(), key);
  if (it == keys.end() || *it != key) return 0.0;
  return impl_->x_[it - keys.begin()];
}

std::vector<double> DistributedNetworkSolver::potentials(const std::vector<NodeKey> &keys) const
{
  const Impl &m = *impl_;
  const auto &own = m.sys_.keys;
  // Own nodes and electrodes here; the others' rows from the directory, values from owners.
  std::vector<NodeKey> need;
  for (NodeKey k : keys)
    if (k != m.high_ && k != m.low_ && !std::binary_search(own.begin(), own.end(), k))
      need.push_back(k);
  std::sort(need.begin(), need.end());
  need.erase(std::unique(need.begin(), need.end()), need.end());
  const std::vector<std::int64_t> found = m.sys_.directory.lookup(need);
  std::vector<int> rows;
  for (std::int64_t r : found)
    if (r != KeyDirectory::kMissing) rows.push_back(static_cast<int>(r));
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  const std::vector<double> at = values_at_rows(m.comm_, m.sys_, m.x_, rows);
  std::vector<double> out(keys.size(), 0.0);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const NodeKey k = keys[i];
    if (k == m.high_) {
      out[i] = m.v_high_;
    } else if (k == m.low_) {
      out[i] = 0.0;
    } else if (std::binary_search(own.begin(), own.end(), k)) {
      out[i] = m.x_[std::lower_bound(own.begin(), own.end(), k) - own.begin()];
    } else {
      const std::int64_t r = found[std::lower_bound(need.begin(), need.end(), k) - need.begin()];
      if (r != KeyDirectory::kMissing)
        out[i] = at[std::lower_bound(rows.begin(), rows.end(), static_cast<int>(r)) - rows.begin()];
    }
  }
  return out;
}

std::size_t DistributedNetworkSolver::memory_bytes() const
{
  const Impl &m = *impl_;
  const std::size_t nnz = m.sys_.columns.size(), n = m.sys_.keys.size();
  // The system (column and value per entry), the kept pattern (a column per entry) and the
  // values at the last setup (a float per entry), the warm start; hypre: the matrix (value and
  // column per entry) and a hierarchy of about the same size again (operator complexity
  // ~1.2, plus interpolation), vectors of n doubles; the assembly's kept buffers.
  const DistributedScratch &w = m.sys_.scratch;
  const std::size_t scratch = w.ends.capacity() * sizeof(int) +
                              w.sorted.capacity() * sizeof(DistributedEntry) +
                              w.bucket.capacity() * sizeof(std::size_t) +
                              w.need.capacity() * sizeof(NodeKey);
  return nnz * (sizeof(int) + sizeof(double) + sizeof(int) + sizeof(float)) +
         n * (sizeof(NodeKey) * 2 + sizeof(double) * 4) +
         nnz * (sizeof(int) + sizeof(double)) * 2 + n * sizeof(double) * 8 + scratch;
}

}  // namespace ohmdem
