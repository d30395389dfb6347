// Assembly, exact reduction and sparse solve of the conduction network.
// Numerics (why each step is there): doc/conduction_network.md.
#include "network/conduction_network.h"

#include "network/multigrid_cg.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace ohmdem {

namespace {

using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Vec = Eigen::VectorXd;

// A refined LDL^T solution is accepted if its scaled edge-wise residual is below this
// (relative to the scaled right-hand side); otherwise the Kron elimination takes over.
constexpr double kDirectAcceptance = 1e-10;

struct RawEdge {
  NodeKey a, b;  // a < b
  double g;
};

// Total order on (a, b, g): parallel edges are then summed in the same order whatever the
// insertion order, which is what makes R bitwise reproducible.
bool canonical_less(const RawEdge &x, const RawEdge &y)
{
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  return x.g < y.g;
}

struct Link {
  int to;
  double g;
};
using Adjacency = std::vector<std::vector<Link>>;

// A node removed before the solve, and how to get its potential back afterwards.
struct Elimination {
  int node;
  int a, b;  // neighbours (b < 0: dangling node, it carries no current: V = V_a)
  double ga, gb;
};

void remove_link(std::vector<Link> &list, int to)
{
  for (auto it = list.begin(); it != list.end(); ++it)
    if (it->to == to) {
      list.erase(it);  // keeps the remaining links in their (canonical) order
      return;
    }
}

void add_link(Adjacency &adj, int a, int b, double g)
{
  for (Link &l : adj[a])
    if (l.to == b) {
      l.g += g;
      for (Link &m : adj[b])
        if (m.to == a) m.g = l.g;
      return;
    }
  adj[a].push_back({b, g});
  adj[b].push_back({a, g});
}

// Exact Kirchhoff reductions: a dangling node (one neighbour) carries no current; a node
// with two neighbours is two conductances in series. Electrodes are never removed.
void reduce(Adjacency &adj, std::vector<char> &alive, std::vector<Elimination> &elim, int ih,
            int il)
{
  const int n = static_cast<int>(adj.size());
  auto reducible = [&](int i) { return alive[i] && i != ih && i != il && adj[i].size() <= 2; };
  std::vector<int> stack;
  for (int i = n - 1; i >= 0; --i)
    if (reducible(i)) stack.push_back(i);
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    if (!reducible(i)) continue;
    alive[i] = 0;
    const std::vector<Link> nb = adj[i];
    adj[i].clear();
    if (nb.empty()) {  // unreachable inside a connected component; kept for safety
      elim.push_back({i, -1, -1, 0.0, 0.0});
      continue;
    }
    for (const Link &l : nb) remove_link(adj[l.to], i);
    if (nb.size() == 1) {
      elim.push_back({i, nb[0].to, -1, nb[0].g, 0.0});
    } else {
      const Link &p = nb[0], &q = nb[1];
      add_link(adj, p.to, q.to, 1.0 / (1.0 / p.g + 1.0 / q.g));  // no overflow of p.g * q.g
      elim.push_back({i, p.to, q.to, p.g, q.g});
    }
    for (const Link &l : nb)
      if (reducible(l.to)) stack.push_back(l.to);
  }
}

// Subtraction-free elimination (Kron reduction, the star-mesh transform of reduce() for any
// degree): node k with total conductance D_k adds g_ik g_jk / D_k between every pair of its
// neighbours. Only positive terms, so every conductance keeps full relative accuracy however
// wide their spread, where an LDL^T of the assembled matrix rounds small conductances away
// in the pivots (and can meet a zero pivot). `order` lists the nodes to eliminate; the
// electrodes must not be in it. Returns the conductance left between ih and il; the records
// let potentials be recovered afterwards (kron_potentials).
struct KronRecord {
  int node;
  double total;
  std::vector<Link> links;
};

double kron_eliminate(Adjacency &adj, const std::vector<int> &order, int ih, int il,
                      std::vector<KronRecord> &records)
{
  std::vector<int> pos(adj.size(), -1);  // position of a neighbour in adj[i], while marked
  records.reserve(records.size() + order.size());
  for (int k : order) {
    KronRecord rec{k, 0.0, std::move(adj[k])};
    adj[k].clear();
    for (const Link &l : rec.links) {
      rec.total += l.g;
      remove_link(adj[l.to], k);
    }
    for (const Link &x : rec.links) {
      std::vector<Link> &list = adj[x.to];
      for (std::size_t p = 0; p < list.size(); ++p) pos[list[p].to] = static_cast<int>(p);
      for (const Link &y : rec.links) {
        if (y.to == x.to) continue;
        // min * (max / D): symmetric in x, y (g_ij and g_ji stay equal) and max / D <= 1.
        const double add = std::min(x.g, y.g) * (std::max(x.g, y.g) / rec.total);
        if (pos[y.to] >= 0) {
          list[pos[y.to]].g += add;
        } else {
          pos[y.to] = static_cast<int>(list.size());
          list.push_back({y.to, add});
        }
      }
      for (const Link &l : list) pos[l.to] = -1;
    }
    records.push_back(std::move(rec));
  }
  double g = 0.0;
  for (const Link &l : adj[ih])
    if (l.to == il) g += l.g;
  return g;
}

// Potentials of Kron-eliminated nodes, last first: V_k = sum g_kj V_j / D_k, a weighted mean.
void kron_potentials(const std::vector<KronRecord> &records, std::vector<double> &v)
{
  for (auto it = records.rbegin(); it != records.rend(); ++it) {
    double sum = 0.0;
    for (const Link &l : it->links) sum += l.g * v[l.to];
    v[it->node] = sum / it->total;
  }
}

}  // namespace

class ConductionNetwork::Impl {
 public:
  std::vector<RawEdge> raw;
  NodeKey high = 0, low = 0;
  bool electrodes = false;
  SolverOptions opt;
  int ignored = 0, loops = 0;

  // Canonical state, rebuilt by prepare() after any change.
  bool prepared = false;
  std::vector<NodeKey> keys;  // sorted, unique
  std::vector<int> ea, eb;    // node indices of raw[k]
  // Last solution (valid while `solved`).
  bool solved = false;
  std::vector<double> volt;
  std::vector<char> comp;
  NetworkSolution last;
  // Warm start: potentials per unit current of the last connected solve, sorted by key.
  std::vector<NodeKey> warm_keys;
  std::vector<double> warm_vals;
  // Direct solver: the symbolic analysis is reused while the sparsity pattern is unchanged.
  struct Ldlt : Eigen::SimplicialLDLT<SpMat> {
    // Multiply-adds of the numeric factorization, sum of squared column counts of L, known
    // after analyzePattern() (Eigen keeps the counts in a protected member).
    double flops() const
    {
      double f = 0.0;
      for (Eigen::Index j = 0; j < m_nonZerosPerCol.size(); ++j)
        f += double(m_nonZerosPerCol[j]) * double(m_nonZerosPerCol[j]);
      return f;
    }
  } ldlt;
  std::vector<int> pattern_outer, pattern_inner;

  void invalidate()
  {
    prepared = false;
    solved = false;
  }
  void prepare();
  int index_of(NodeKey k) const
  {
    auto it = std::lower_bound(keys.begin(), keys.end(), k);
    return (it != keys.end() && *it == k) ? static_cast<int>(it - keys.begin()) : -1;
  }
  NetworkSolution solve(double current, SolverKind kind);

 private:
  void solve_system(const Adjacency &adj, const std::vector<int> &unk, int ih, int il,
                    double current, SolverKind kind, std::vector<double> &v, NetworkSolution &s);
  void analyze(const SpMat &A);
  SolverKind choose(const SpMat &A, SolverKind kind);
  Vec warm_guess(const Adjacency &adj, const std::vector<int> &unk, int m, double current) const;
};

void ConductionNetwork::Impl::prepare()
{
  if (prepared) return;
  std::sort(raw.begin(), raw.end(), canonical_less);
  // Node indices without a binary search per edge end: the a's are already sorted; the b's
  // are sorted once with their edge numbers, then both are walked against the merged keys.
  const std::size_t ne = raw.size();
  std::vector<std::pair<NodeKey, std::size_t>> bs(ne);
  for (std::size_t k = 0; k < ne; ++k) bs[k] = {raw[k].b, k};
  std::sort(bs.begin(), bs.end());
  keys.clear();
  keys.reserve(ne + 1);
  std::size_t i = 0, j = 0;
  while (i < ne || j < ne) {
    const NodeKey next = j == ne || (i < ne && raw[i].a < bs[j].first) ? raw[i].a : bs[j].first;
    if (keys.empty() || keys.back() != next) keys.push_back(next);
    if (i < ne && raw[i].a == next)
      ++i;
    else
      ++j;
  }
  ea.resize(ne);
  eb.resize(ne);
  std::size_t n = 0;
  for (std::size_t k = 0; k < ne; ++k) {
    while (keys[n] != raw[k].a) ++n;
    ea[k] = static_cast<int>(n);
  }
  n = 0;
  for (const auto &[b, k] : bs) {
    while (keys[n] != b) ++n;
    eb[k] = static_cast<int>(n);
  }
  volt.assign(keys.size(), 0.0);
  comp.assign(keys.size(), 0);
  solved = false;
  prepared = true;
}

NetworkSolution ConductionNetwork::Impl::solve(double current, SolverKind kind)
{
  if (!electrodes)
    throw std::invalid_argument("ConductionNetwork::solve: set_electrodes() was not called");
  if (!std::isfinite(current) || current == 0.0)
    throw std::invalid_argument("ConductionNetwork::solve: current must be finite and non-zero");
  prepare();
  const int n = static_cast<int>(keys.size());
  std::fill(volt.begin(), volt.end(), 0.0);
  std::fill(comp.begin(), comp.end(), 0);
  NetworkSolution s;
  s.current = current;
  s.ignored_conductances = ignored;
  s.self_loops = loops;
  solved = true;
  last = s;

  const int ih = index_of(high), il = index_of(low);
  if (high == low) {  // one body is both electrodes: a short circuit
    s.connected = true;
    s.method = SolveMethod::ClosedForm;
    s.floating_nodes_dropped = n - (ih >= 0 ? 1 : 0);
    if (ih >= 0) comp[ih] = 1;
    return last = s;
  }
  auto no_path = [&]() {
    s.resistance = s.voltage_drop = std::numeric_limits<double>::infinity();
    s.floating_nodes_dropped = n;
    return last = s;
  };
  if (ih < 0 || il < 0) return no_path();

  // Merge parallel edges (raw is sorted, so each pair is contiguous) into adjacency lists.
  Adjacency adj(n);
  for (std::size_t k = 0; k < raw.size();) {
    double g = 0.0;
    std::size_t j = k;
    for (; j < raw.size() && raw[j].a == raw[k].a && raw[j].b == raw[k].b; ++j) g += raw[j].g;
    adj[ea[k]].push_back({eb[k], g});
    adj[eb[k]].push_back({ea[k], g});
    k = j;
  }
  // Only the component holding the high electrode can carry current.
  std::vector<int> queue{ih};
  comp[ih] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (const Link &l : adj[queue[q]])
      if (!comp[l.to]) {
        comp[l.to] = 1;
        queue.push_back(l.to);
      }
  if (!comp[il]) {
    std::fill(comp.begin(), comp.end(), 0);
    return no_path();
  }
  s.connected = true;
  s.floating_nodes_dropped = n - static_cast<int>(queue.size());
  for (std::size_t k = 0; k < raw.size(); ++k) s.conducting_edges += comp[ea[k]];
  for (int i = 0; i < n; ++i)
    if (!comp[i]) adj[i].clear();

  std::vector<char> alive(comp);
  std::vector<Elimination> elim;
  if (opt.reduce_series) reduce(adj, alive, elim, ih, il);
  s.eliminated_nodes = static_cast<int>(elim.size());

  // Unknowns: the surviving nodes except the grounded electrode, in key order.
  std::vector<int> unk(n, -1);
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (alive[i] && i != il) unk[i] = m++;
  if (m == 1) {
    // Every surviving edge joins the electrodes directly (the bearing): R = 1 / sum(g).
    // After merging, the only link of ih goes to il and holds that sum.
    double g = 0.0;
    for (const Link &l : adj[ih]) g += l.g;
    s.method = SolveMethod::ClosedForm;
    s.resistance = 1.0 / g;
    volt[ih] = current * s.resistance;
  } else {
    s.unknowns = m;
    solve_system(adj, unk, ih, il, current, kind, volt, s);
  }
  s.voltage_drop = s.resistance * current;
  // Potentials of the eliminated nodes, last eliminated first (its neighbours are known).
  for (auto it = elim.rbegin(); it != elim.rend(); ++it) {
    if (it->a < 0)
      volt[it->node] = 0.0;
    else if (it->b < 0)
      volt[it->node] = volt[it->a];
    else
      volt[it->node] = (it->ga * volt[it->a] + it->gb * volt[it->b]) / (it->ga + it->gb);
  }
  warm_keys.clear();
  warm_vals.clear();
  for (int i = 0; i < n; ++i)
    if (comp[i]) {
      warm_keys.push_back(keys[i]);
      warm_vals.push_back(volt[i] / current);
    }
  return last = s;
}

// Initial guess for CG: last potentials per unit current (looked up by key: both lists are
// sorted), new nodes get the mean of their already-guessed neighbours.
Vec ConductionNetwork::Impl::warm_guess(const Adjacency &adj, const std::vector<int> &unk, int m,
                                        double current) const
{
  Vec v0 = Vec::Zero(m);
  std::vector<char> known(keys.size(), 0);
  std::size_t w = 0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    while (w < warm_keys.size() && warm_keys[w] < keys[i]) ++w;
    if (unk[i] >= 0 && w < warm_keys.size() && warm_keys[w] == keys[i]) {
      v0[unk[i]] = warm_vals[w] * current;
      known[i] = 1;
    }
  }
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (unk[i] < 0 || known[i]) continue;
    double sum = 0.0;
    int cnt = 0;
    for (const Link &l : adj[i])
      if (unk[l.to] < 0 || known[l.to]) {  // a surviving neighbour without unknown: ground
        sum += unk[l.to] >= 0 ? v0[unk[l.to]] : 0.0;
        ++cnt;
      }
    if (cnt) v0[unk[i]] = sum / cnt;
  }
  return v0;
}

void ConductionNetwork::Impl::analyze(const SpMat &A)
{
  const int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
  const bool same = pattern_outer.size() == static_cast<std::size_t>(A.outerSize() + 1) &&
                    pattern_inner.size() == static_cast<std::size_t>(A.nonZeros()) &&
                    std::equal(pattern_outer.begin(), pattern_outer.end(), outer) &&
                    std::equal(pattern_inner.begin(), pattern_inner.end(), inner);
  if (!same) {
    ldlt.analyzePattern(A);
    pattern_outer.assign(outer, outer + A.outerSize() + 1);
    pattern_inner.assign(inner, inner + A.nonZeros());
  }
}

// Auto: a deterministic choice from the sparsity pattern only (never from timings, which would
// make R depend on the machine load). Small systems go direct; in between, the symbolic
// analysis predicts the factorization cost, compared with that of a few hundred CG matvecs.
SolverKind ConductionNetwork::Impl::choose(const SpMat &A, SolverKind kind)
{
  if (kind != SolverKind::Auto) return kind;
  const Eigen::Index m = A.rows();
  if (m <= opt.auto_direct_unknowns) return SolverKind::Direct;
  if (m > opt.auto_cg_unknowns) return SolverKind::ConjugateGradient;
  analyze(A);
  return ldlt.flops() <= opt.auto_flops_per_nonzero * double(A.nonZeros())
             ? SolverKind::Direct
             : SolverKind::ConjugateGradient;
}

void ConductionNetwork::Impl::solve_system(const Adjacency &adj, const std::vector<int> &unk,
                                           int ih, int il, double current, SolverKind kind,
                                           std::vector<double> &v, NetworkSolution &s)
{
  const int n = static_cast<int>(adj.size()), m = s.unknowns;
  // Grounded Laplacian L (row/column of `il` removed), assembled in key order.
  std::vector<Eigen::Triplet<double, int>> trip;
  Vec diag(m);
  for (int i = 0; i < n; ++i) {
    if (unk[i] < 0) continue;
    double d = 0.0;
    for (const Link &l : adj[i]) {
      d += l.g;
      if (l.to != il) trip.emplace_back(unk[i], unk[l.to], -l.g);
    }
    trip.emplace_back(unk[i], unk[i], d);
    diag[unk[i]] = d;
  }
  SpMat A(m, m);
  A.setFromTriplets(trip.begin(), trip.end());
  trip = {};
  // Symmetric diagonal scaling A = D L D, D = diag(L)^(-1/2): unit diagonal, so conductances
  // spread over many decades no longer dominate the CG stopping test or the pivots.
  const Vec d = diag.cwiseSqrt().cwiseInverse();
  for (int k = 0; k < A.outerSize(); ++k)
    for (SpMat::InnerIterator it(A, k); it; ++it) it.valueRef() *= d[it.row()] * d[it.col()];
  const int h = unk[ih];
  Vec b = Vec::Zero(m);
  b[h] = d[h] * current;
  Vec y;

  const bool chose = kind == SolverKind::Auto;
  kind = choose(A, kind);
  const bool multigrid = opt.preconditioner == Preconditioner::Multigrid ||
                         (chose && kind == SolverKind::ConjugateGradient &&
                          m >= opt.auto_multigrid_unknowns);
  auto run_cg = [&](int maxit) {
    Vec y0 = Vec::Zero(m);
    if (opt.warm_start && !warm_keys.empty())
      y0 = warm_guess(adj, unk, m, current).cwiseQuotient(d);
    auto run = [&](auto &cg) {
      cg.setTolerance(opt.cg_tolerance);
      cg.setMaxIterations(maxit);
      cg.compute(A);
      y = cg.solveWithGuess(b, y0);
      s.iterations = static_cast<int>(cg.iterations());
      s.method = SolveMethod::ConjugateGradient;
      return cg.info() == Eigen::Success;
    };
    if (multigrid) {
      A.makeCompressed();  // symmetric: its compressed columns are its compressed rows
      y = y0;
      const MultigridResult r = multigrid_cg(m, A.outerIndexPtr(), A.innerIndexPtr(),
                                             A.valuePtr(), b.data(), y.data(), opt.cg_tolerance,
                                             maxit);
      s.iterations = r.iterations;
      s.method = SolveMethod::MultigridCG;
      return r.converged;
    }
    if (opt.preconditioner == Preconditioner::IncompleteCholesky) {
      Eigen::ConjugateGradient<
          SpMat, Eigen::Lower | Eigen::Upper,
          Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
          cg;
      return run(cg);
    }
    Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper> cg;
    return run(cg);
  };
  // Kirchhoff residual b - L v evaluated edge by edge from potential differences. Unlike
  // b - A y it does not see the rounding of the assembled diagonal (sums of conductances
  // spread over decades); R itself is well conditioned (monotone in every g, homogeneous of
  // degree -1), and the edge-wise forms keep that.
  auto potential = [&](const Vec &y, int i) { return i == il ? 0.0 : d[unk[i]] * y[unk[i]]; };
  auto graph_residual = [&](const Vec &y) {
    Vec r(m);
    for (int i = 0; i < n; ++i) {
      if (unk[i] < 0) continue;
      const double vi = potential(y, i);
      double acc = i == ih ? current : 0.0;
      for (const Link &l : adj[i]) acc -= l.g * (vi - potential(y, l.to));
      r[unk[i]] = acc;
    }
    return r;
  };

  // R and potentials from an approximate solution y (CG, or LDL^T + refinement).
  auto finish = [&](const Vec &y) {
    s.relative_residual = graph_residual(y).norm() / std::fabs(current);
    // R from the energy (Thomson) functional 2 I V_h - v^T L v: a lower bound of R whose
    // error is ||v - v*||_L^2 / I^2, quadratic in the solution error (also for a warm
    // start). The energy is summed edge by edge, sum g (V_a - V_b)^2, for the reason above.
    double energy = 0.0;
    for (int i = 0; i < n; ++i) {
      if (unk[i] < 0) continue;
      const double vi = potential(y, i);
      for (const Link &l : adj[i])
        if (l.to == il || l.to > i) {
          const double dv = vi - potential(y, l.to);
          energy += l.g * dv * dv;
        }
    }
    s.resistance = (2.0 * current * potential(y, ih) - energy) / (current * current);
    for (int i = 0; i < n; ++i)
      if (unk[i] >= 0) v[i] = potential(y, i);
  };

  if (kind == SolverKind::ConjugateGradient &&
      run_cg(opt.cg_max_iterations > 0 ? opt.cg_max_iterations : std::max(1000, 2 * m)) &&
      y.allFinite()) {
    // CG converged on the rounded matrix A. Accept it if the solution also satisfies the exact
    // (edge-wise) equations to sqrt(tol), and V_h / I agrees with the energy R to sqrt(tol):
    // R's error being quadratic, that keeps R accurate. Both fail only when the spread of
    // conductances approaches 1/eps and A has lost what matters (measured: ~1e-8 and 1e-10
    // normally, 2e-6 and 1e-7 at 20 decades where R is still right to 1e-14).
    const double loose = std::sqrt(opt.cg_tolerance);
    if (graph_residual(y).cwiseProduct(d).norm() <= loose * b.norm()) {
      finish(y);
      if (std::fabs(v[ih] / current - s.resistance) <= loose * s.resistance) return;
    }
  }
  // Direct (or CG that did not converge: correctness before speed): sparse LDL^T of the
  // scaled matrix, then iterative refinement on the edge-wise residual while it shrinks
  // (usually 1-3 steps): the rounded factors only serve as a preconditioner there.
  s.iterations = 0;
  s.method = SolveMethod::Direct;
  analyze(A);
  ldlt.factorize(A);
  if (ldlt.info() == Eigen::Success) {
    y = ldlt.solve(b);
    double last = std::numeric_limits<double>::infinity(), norm = last;
    for (int step = 0; step < 4 && y.allFinite(); ++step) {
      const Vec rs = graph_residual(y).cwiseProduct(d);  // scaled: D (b - L v)
      norm = rs.norm();
      if (!(norm > 1e-15 * b.norm()) || norm > 0.5 * last) break;
      last = norm;
      y += ldlt.solve(rs);
      ++s.iterations;
    }
    if (y.allFinite() && norm <= kDirectAcceptance * b.norm()) {
      finish(y);
      return;
    }
  }
  // The factors were too poor for refinement (a spread of conductances near 1/eps makes the
  // assembled matrix numerically singular): the subtraction-free Kron elimination is exact
  // to rounding whatever the spread, 4-10x slower than LDL^T, so only a fallback.
  s.iterations = 0;
  s.method = SolveMethod::Elimination;
  y = Vec::Zero(m);
  std::vector<int> node_of(m);
  for (int i = 0; i < n; ++i)
    if (unk[i] >= 0) node_of[unk[i]] = i;
  std::vector<int> order;
  order.reserve(m);
  const auto &pinv = ldlt.permutationPinv();  // the fill-reducing order of analyze()
  for (int k = 0; k < m; ++k)
    if (pinv.indices()[k] != h) order.push_back(node_of[pinv.indices()[k]]);
  Adjacency work = adj;
  std::vector<KronRecord> records;
  s.resistance = 1.0 / kron_eliminate(work, order, ih, il, records);
  v[ih] = current * s.resistance;
  v[il] = 0.0;
  kron_potentials(records, v);
  for (int i = 0; i < n; ++i)
    if (unk[i] >= 0) y[unk[i]] = v[i] / d[unk[i]];
  s.relative_residual = graph_residual(y).norm() / std::fabs(current);
}

// --- public interface --------------------------------------------------------------------

const char *to_string(SolveMethod m)
{
  switch (m) {
    case SolveMethod::ClosedForm:
      return "closed-form";
    case SolveMethod::Direct:
      return "direct";
    case SolveMethod::Elimination:
      return "elimination";
    case SolveMethod::ConjugateGradient:
      return "cg";
    case SolveMethod::MultigridCG:
      return "cg-amg";
    case SolveMethod::None:
      break;
  }
  return "none";
}

ConductionNetwork::ConductionNetwork() : impl_(std::make_unique<Impl>()) {}
ConductionNetwork::~ConductionNetwork() = default;
ConductionNetwork::ConductionNetwork(ConductionNetwork &&) noexcept = default;
ConductionNetwork &ConductionNetwork::operator=(ConductionNetwork &&) noexcept = default;

void ConductionNetwork::clear()
{
  impl_->raw.clear();
  impl_->ignored = impl_->loops = 0;
  impl_->last = NetworkSolution{};
  impl_->invalidate();
}

void ConductionNetwork::reset()
{
  clear();
  impl_->warm_keys.clear();
  impl_->warm_vals.clear();
}

void ConductionNetwork::reserve(std::size_t edges)
{
  impl_->raw.reserve(edges);
}

void ConductionNetwork::add_conductance(NodeKey a, NodeKey b, double g)
{
  if (!(g > 0.0) || !std::isfinite(g)) {  // also catches NaN
    ++impl_->ignored;
    return;
  }
  if (a == b) {
    ++impl_->loops;
    return;
  }
  impl_->raw.push_back({std::min(a, b), std::max(a, b), g});
  impl_->invalidate();
}

void ConductionNetwork::set_electrodes(NodeKey high, NodeKey low)
{
  impl_->high = high;
  impl_->low = low;
  impl_->electrodes = true;
  impl_->solved = false;
}

void ConductionNetwork::set_options(const SolverOptions &options)
{
  impl_->opt = options;
}
const SolverOptions &ConductionNetwork::options() const
{
  return impl_->opt;
}

NetworkSolution ConductionNetwork::solve(double current)
{
  return impl_->solve(current, impl_->opt.kind);
}

NetworkSolution ConductionNetwork::solve(double current, SolverKind kind)
{
  return impl_->solve(current, kind);
}

double ConductionNetwork::potential(NodeKey key) const
{
  if (!impl_->solved) return 0.0;
  const int i = impl_->index_of(key);
  return i >= 0 ? impl_->volt[i] : 0.0;
}

bool ConductionNetwork::is_connected(NodeKey key) const
{
  if (!impl_->solved) return false;
  const int i = impl_->index_of(key);
  return i >= 0 && impl_->comp[i];
}

const NetworkSolution &ConductionNetwork::last_solution() const
{
  return impl_->last;
}
NodeKey ConductionNetwork::high() const
{
  return impl_->high;
}
NodeKey ConductionNetwork::low() const
{
  return impl_->low;
}
bool ConductionNetwork::has_electrodes() const
{
  return impl_->electrodes;
}
std::size_t ConductionNetwork::num_edges() const
{
  return impl_->raw.size();
}

std::vector<NetworkEdge> ConductionNetwork::edges() const
{
  impl_->prepare();  // logically const: only sorts and caches
  const Impl &p = *impl_;
  std::vector<NetworkEdge> out;
  out.reserve(p.raw.size());
  for (std::size_t k = 0; k < p.raw.size(); ++k) {
    const bool on = p.solved && p.comp[p.ea[k]];
    const double i = on ? p.raw[k].g * (p.volt[p.ea[k]] - p.volt[p.eb[k]]) : 0.0;
    out.push_back({p.raw[k].a, p.raw[k].b, p.raw[k].g, i, on});
  }
  return out;
}

std::vector<NetworkNode> ConductionNetwork::nodes() const
{
  impl_->prepare();
  const Impl &p = *impl_;
  std::vector<NetworkNode> out;
  out.reserve(p.keys.size());
  for (std::size_t i = 0; i < p.keys.size(); ++i)
    out.push_back({p.keys[i], p.solved ? p.volt[i] : 0.0, p.solved && p.comp[i] != 0});
  return out;
}

}  // namespace ohmdem
