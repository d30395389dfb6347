// SPDX-License-Identifier: GPL-2.0-or-later
// The solve strategy of a conduction network; see network_solve.h.
#include "network/network_solve.h"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <cmath>
#include <limits>

#include "network/multigrid_cg.h"
#include "network/network_reductions.h"

namespace ohmdem::net {

namespace {
// A refined LDL^T solution is accepted if its scaled edge-wise residual is below this
// (relative to the scaled right-hand side); otherwise the Kron elimination takes over.
constexpr double kDirectAcceptance = 1e-10;
}  // namespace

double SystemSolver::Ldlt::flops() const
{
  double f = 0.0;
  for (Eigen::Index j = 0; j < m_nonZerosPerCol.size(); ++j)
    f += double(m_nonZerosPerCol[j]) * double(m_nonZerosPerCol[j]);
  return f;
}

void SystemSolver::analyze(const SpMat &A)
{
  const int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
  const bool same = pattern_outer_.size() == static_cast<std::size_t>(A.outerSize() + 1) &&
                    pattern_inner_.size() == static_cast<std::size_t>(A.nonZeros()) &&
                    std::equal(pattern_outer_.begin(), pattern_outer_.end(), outer) &&
                    std::equal(pattern_inner_.begin(), pattern_inner_.end(), inner);
  if (!same) {
    ldlt_.analyzePattern(A);
    pattern_outer_.assign(outer, outer + A.outerSize() + 1);
    pattern_inner_.assign(inner, inner + A.nonZeros());
  }
}

// Auto: a deterministic choice from the sparsity pattern only (never from timings, which would
// make R depend on the machine load). Small systems go direct; in between, the symbolic
// analysis predicts the factorization cost, compared with that of a few hundred CG matvecs.
SolverKind SystemSolver::choose(const SpMat &A, SolverKind kind, const SolverOptions &opt)
{
  if (kind != SolverKind::Auto) return kind;
  const Eigen::Index m = A.rows();
  if (m <= opt.auto_direct_unknowns) return SolverKind::Direct;
  if (m > opt.auto_cg_unknowns) return SolverKind::ConjugateGradient;
  analyze(A);
  return ldlt_.flops() <= opt.auto_flops_per_nonzero * double(A.nonZeros())
             ? SolverKind::Direct
             : SolverKind::ConjugateGradient;
}

// One solve: the scaled system and the three strategies tried in turn.
class SystemSolver::Run {
 public:
  Run(SystemSolver &owner, const ReducedSystem &sys, const SolverOptions &opt,
      const WarmStart &warm, std::vector<double> &v, NetworkSolution &s)
      : owner_(owner),
        sys_(sys),
        opt_(opt),
        warm_(warm),
        v_(v),
        s_(s),
        n_(static_cast<int>(sys.adj.size())),
        m_(s.unknowns)
  {
  }
  void assemble();
  const SpMat &matrix() const { return A_; }
  bool conjugate_gradient(SolverKind kind, bool chose);
  bool direct();
  void eliminate();

 private:
  double potential(const Vec &y, int i) const
  {
    return i == sys_.il ? 0.0 : d_[sys_.unk[i]] * y[sys_.unk[i]];
  }
  Vec graph_residual(const Vec &y) const;
  void finish(const Vec &y);
  bool run_cg(int maxit, bool multigrid);
  Vec warm_guess() const;

  SystemSolver &owner_;
  const ReducedSystem &sys_;
  const SolverOptions &opt_;
  const WarmStart &warm_;
  std::vector<double> &v_;
  NetworkSolution &s_;
  const int n_, m_;
  SpMat A_;
  Vec d_, b_, y_;
};

// Grounded Laplacian L (row/column of `il` removed), assembled in key order, then the
// symmetric diagonal scaling A = D L D, D = diag(L)^(-1/2): unit diagonal, so conductances
// spread over many decades no longer dominate the CG stopping test or the pivots.
void SystemSolver::Run::assemble()
{
  std::vector<Eigen::Triplet<double, int>> trip;
  Vec diag(m_);
  for (int i = 0; i < n_; ++i) {
    if (sys_.unk[i] < 0) continue;
    double d = 0.0;
    for (const Link &l : sys_.adj[i]) {
      d += l.g;
      if (l.to != sys_.il) trip.emplace_back(sys_.unk[i], sys_.unk[l.to], -l.g);
    }
    trip.emplace_back(sys_.unk[i], sys_.unk[i], d);
    diag[sys_.unk[i]] = d;
  }
  A_ = SpMat(m_, m_);
  A_.setFromTriplets(trip.begin(), trip.end());
  trip = {};
  d_ = diag.cwiseSqrt().cwiseInverse();
  for (int k = 0; k < A_.outerSize(); ++k)
    for (SpMat::InnerIterator it(A_, k); it; ++it) it.valueRef() *= d_[it.row()] * d_[it.col()];
  const int h = sys_.unk[sys_.ih];
  b_ = Vec::Zero(m_);
  b_[h] = d_[h] * sys_.current;
}

// Kirchhoff residual b - L v evaluated edge by edge from potential differences. Unlike
// b - A y it does not see the rounding of the assembled diagonal (sums of conductances
// spread over decades); R itself is well conditioned (monotone in every g, homogeneous of
// degree -1), and the edge-wise forms keep that.
Vec SystemSolver::Run::graph_residual(const Vec &y) const
{
  Vec r(m_);
  for (int i = 0; i < n_; ++i) {
    if (sys_.unk[i] < 0) continue;
    const double vi = potential(y, i);
    double acc = i == sys_.ih ? sys_.current : 0.0;
    for (const Link &l : sys_.adj[i]) acc -= l.g * (vi - potential(y, l.to));
    r[sys_.unk[i]] = acc;
  }
  return r;
}

// R and potentials from an approximate solution y (CG, or LDL^T + refinement).
void SystemSolver::Run::finish(const Vec &y)
{
  const double current = sys_.current;
  s_.relative_residual = graph_residual(y).norm() / std::fabs(current);
  // R from the energy (Thomson) functional 2 I V_h - v^T L v: a lower bound of R whose
  // error is ||v - v*||_L^2 / I^2, quadratic in the solution error (also for a warm
  // start). The energy is summed edge by edge, sum g (V_a - V_b)^2, for the reason above.
  double energy = 0.0;
  for (int i = 0; i < n_; ++i) {
    if (sys_.unk[i] < 0) continue;
    const double vi = potential(y, i);
    for (const Link &l : sys_.adj[i])
      if (l.to == sys_.il || l.to > i) {
        const double dv = vi - potential(y, l.to);
        energy += l.g * dv * dv;
      }
  }
  s_.resistance = (2.0 * current * potential(y, sys_.ih) - energy) / (current * current);
  for (int i = 0; i < n_; ++i)
    if (sys_.unk[i] >= 0) v_[i] = potential(y, i);
}

// Initial guess for CG: last potentials per unit current (looked up by key: both lists are
// sorted), new nodes get the mean of their already-guessed neighbours.
Vec SystemSolver::Run::warm_guess() const
{
  const auto &keys = sys_.keys;
  const auto &unk = sys_.unk;
  Vec v0 = Vec::Zero(m_);
  std::vector<char> known(keys.size(), 0);
  std::size_t w = 0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    while (w < warm_.keys.size() && warm_.keys[w] < keys[i]) ++w;
    if (unk[i] >= 0 && w < warm_.keys.size() && warm_.keys[w] == keys[i]) {
      v0[unk[i]] = warm_.values[w] * sys_.current;
      known[i] = 1;
    }
  }
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (unk[i] < 0 || known[i]) continue;
    double sum = 0.0;
    int cnt = 0;
    for (const Link &l : sys_.adj[i])
      if (unk[l.to] < 0 || known[l.to]) {  // a surviving neighbour without unknown: ground
        sum += unk[l.to] >= 0 ? v0[unk[l.to]] : 0.0;
        ++cnt;
      }
    if (cnt) v0[unk[i]] = sum / cnt;
  }
  return v0;
}

bool SystemSolver::Run::run_cg(int maxit, bool multigrid)
{
  Vec y0 = Vec::Zero(m_);
  if (opt_.warm_start && !warm_.keys.empty()) y0 = warm_guess().cwiseQuotient(d_);
  auto run = [&](auto &cg) {
    cg.setTolerance(opt_.cg_tolerance);
    cg.setMaxIterations(maxit);
    cg.compute(A_);
    y_ = cg.solveWithGuess(b_, y0);
    s_.iterations = static_cast<int>(cg.iterations());
    s_.method = SolveMethod::ConjugateGradient;
    return cg.info() == Eigen::Success;
  };
  if (multigrid) {
    A_.makeCompressed();  // symmetric: its compressed columns are its compressed rows
    y_ = y0;
    const MultigridResult r =
        multigrid_cg(m_, A_.outerIndexPtr(), A_.innerIndexPtr(), A_.valuePtr(), b_.data(),
                     y_.data(), opt_.cg_tolerance, maxit);
    s_.iterations = r.iterations;
    s_.method = SolveMethod::MultigridCG;
    return r.converged;
  }
  if (opt_.preconditioner == Preconditioner::IncompleteCholesky) {
    Eigen::ConjugateGradient<
        SpMat, Eigen::Lower | Eigen::Upper,
        Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
        cg;
    return run(cg);
  }
  Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper> cg;
  return run(cg);
}

// CG if chosen. Accepted if the solution also satisfies the exact (edge-wise) equations to
// sqrt(tol), and V_h / I agrees with the energy R to sqrt(tol): R's error being quadratic,
// that keeps R accurate. Both fail only when the spread of conductances approaches 1/eps and
// A has lost what matters (measured: ~1e-8 and 1e-10 normally, 2e-6 and 1e-7 at 20 decades
// where R is still right to 1e-14).
bool SystemSolver::Run::conjugate_gradient(SolverKind kind, bool chose)
{
  const bool multigrid =
      opt_.preconditioner == Preconditioner::Multigrid ||
      (chose && kind == SolverKind::ConjugateGradient && m_ >= opt_.auto_multigrid_unknowns);
  if (!(kind == SolverKind::ConjugateGradient &&
        run_cg(opt_.cg_max_iterations > 0 ? opt_.cg_max_iterations : std::max(1000, 2 * m_),
               multigrid) &&
        y_.allFinite()))
    return false;
  const double loose = std::sqrt(opt_.cg_tolerance);
  if (graph_residual(y_).cwiseProduct(d_).norm() > loose * b_.norm()) return false;
  finish(y_);
  return std::fabs(v_[sys_.ih] / sys_.current - s_.resistance) <= loose * s_.resistance;
}

// Sparse LDL^T of the scaled matrix, then iterative refinement on the edge-wise residual
// while it shrinks (usually 1-3 steps): the rounded factors only serve as a preconditioner.
bool SystemSolver::Run::direct()
{
  s_.iterations = 0;
  s_.method = SolveMethod::Direct;
  owner_.analyze(A_);
  auto &ldlt = owner_.ldlt_;
  ldlt.factorize(A_);
  if (ldlt.info() != Eigen::Success) return false;
  y_ = ldlt.solve(b_);
  double last = std::numeric_limits<double>::infinity(), norm = last;
  for (int step = 0; step < 4 && y_.allFinite(); ++step) {
    const Vec rs = graph_residual(y_).cwiseProduct(d_);  // scaled: D (b - L v)
    norm = rs.norm();
    if (!(norm > 1e-15 * b_.norm()) || norm > 0.5 * last) break;
    last = norm;
    y_ += ldlt.solve(rs);
    ++s_.iterations;
  }
  if (!(y_.allFinite() && norm <= kDirectAcceptance * b_.norm())) return false;
  finish(y_);
  return true;
}

// The factors were too poor for refinement (a spread of conductances near 1/eps makes the
// assembled matrix numerically singular): the subtraction-free Kron elimination is exact
// to rounding whatever the spread, 4-10x slower than LDL^T, so only a fallback.
void SystemSolver::Run::eliminate()
{
  s_.iterations = 0;
  s_.method = SolveMethod::Elimination;
  y_ = Vec::Zero(m_);
  std::vector<int> node_of(m_);
  for (int i = 0; i < n_; ++i)
    if (sys_.unk[i] >= 0) node_of[sys_.unk[i]] = i;
  std::vector<int> order;
  order.reserve(m_);
  const int h = sys_.unk[sys_.ih];
  const auto &pinv = owner_.ldlt_.permutationPinv();  // the fill-reducing order of analyze()
  for (int k = 0; k < m_; ++k)
    if (pinv.indices()[k] != h) order.push_back(node_of[pinv.indices()[k]]);
  Adjacency work = sys_.adj;
  std::vector<KronRecord> records;
  s_.resistance = 1.0 / kron_eliminate(work, order, sys_.ih, sys_.il, records);
  v_[sys_.ih] = sys_.current * s_.resistance;
  v_[sys_.il] = 0.0;
  kron_potentials(records, v_);
  for (int i = 0; i < n_; ++i)
    if (sys_.unk[i] >= 0) y_[sys_.unk[i]] = v_[i] / d_[sys_.unk[i]];
  s_.relative_residual = graph_residual(y_).norm() / std::fabs(sys_.current);
}

void SystemSolver::solve(const ReducedSystem &sys, SolverKind kind, const SolverOptions &opt,
                         const WarmStart &warm, std::vector<double> &v, NetworkSolution &s)
{
  Run run(*this, sys, opt, warm, v, s);
  run.assemble();
  const bool chose = kind == SolverKind::Auto;
  // Direct also when CG did not converge: correctness before speed.
  if (run.conjugate_gradient(choose(run.matrix(), kind, opt), chose)) return;
  if (run.direct()) return;
  run.eliminate();
}

}  // namespace ohmdem::net
