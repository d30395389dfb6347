// SPDX-License-Identifier: GPL-2.0-or-later
// The complex admittance network; see complex_network.h.
#include "network/complex_network.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace ohmdem {

namespace {

using cplx = std::complex<double>;

bool edge_less(const ComplexEdge &x, const ComplexEdge &y)
{
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  if (x.y.real() != y.y.real()) return x.y.real() < y.y.real();
  return x.y.imag() < y.y.imag();
}

struct Eliminated {
  int node, p, q;  // q = -1: a dangling node
  cplx yp, yq;
};

int index_of(const std::vector<NodeKey> &keys, NodeKey k)
{
  return static_cast<int>(std::lower_bound(keys.begin(), keys.end(), k) - keys.begin());
}

}  // namespace

std::complex<double> ComplexSolution::potential(NodeKey key) const
{
  const auto it = std::lower_bound(keys.begin(), keys.end(), key);
  if (it == keys.end() || *it != key) return {0.0, 0.0};
  return potentials[static_cast<std::size_t>(it - keys.begin())];
}

ComplexSolution solve_complex_network(std::vector<ComplexEdge> edges, NodeKey high, NodeKey low,
                                      double current, const ComplexOptions &options)
{
  if (high == low) throw std::invalid_argument("solve_complex_network: high == low electrode");
  if (!(current > 0.0) || !std::isfinite(current))
    throw std::invalid_argument("solve_complex_network: the current must be finite and > 0");
  for (ComplexEdge &e : edges) {
    if (e.a == e.b) throw std::invalid_argument("solve_complex_network: a self loop");
    if (!std::isfinite(e.y.real()) || !std::isfinite(e.y.imag()))
      throw std::invalid_argument("solve_complex_network: a non-finite admittance");
    if (e.b < e.a) std::swap(e.a, e.b);
  }
  // Canonical order: parallel edges summed in the same order whatever the caller's order.
  std::sort(edges.begin(), edges.end(), edge_less);

  ComplexSolution s;
  std::vector<NodeKey> &keys = s.keys;
  keys = {high, low};
  for (const ComplexEdge &e : edges) {
    keys.push_back(e.a);
    keys.push_back(e.b);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  const int n = static_cast<int>(keys.size());

  // The component of the low electrode over non-zero admittances: a node outside it floats
  // (its potential is undetermined; no current reaches it).
  std::vector<std::vector<int>> adj(n);
  for (const ComplexEdge &e : edges) {
    if (e.y == cplx(0.0, 0.0)) continue;
    const int a = index_of(keys, e.a), b = index_of(keys, e.b);
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  std::vector<char> &comp = s.in_component;
  comp.assign(n, 0);
  const int ilow = index_of(keys, low), ihigh = index_of(keys, high);
  std::vector<int> queue{ilow};
  comp[ilow] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (int j : adj[queue[q]])
      if (!comp[j]) comp[j] = 1, queue.push_back(j);
  s.potentials.assign(n, cplx(0.0, 0.0));
  s.connected = comp[ihigh] != 0;
  if (!s.connected) {
    s.z = {std::numeric_limits<double>::infinity(), 0.0};
    return s;
  }

  // Parallel edges merged (in the canonical order) into one admittance per node pair, on
  // the component only.
  std::vector<std::map<int, cplx>> adj2(n);
  for (const ComplexEdge &e : edges) {
    const int a = index_of(keys, e.a), b = index_of(keys, e.b);
    if (e.y == cplx(0.0, 0.0) || !comp[a]) continue;
    adj2[a][b] += e.y;
    adj2[b][a] += e.y;
  }
  // Exact elimination (options.reduce_series) of the nodes of degree 1 (no current) and 2
  // (two admittances in series, y1 y2 / (y1 + y2)), lowest index first: in the nodal matrix
  // the Schur complement y1 - y1^2 / (y1 + y2) cancels when y2 << y1 (a metallic contact in
  // series with an idle gap), the series formula does not.
  std::vector<Eliminated> gone;
  if (options.reduce_series) {
    std::set<int> todo;
    for (int i = 0; i < n; ++i)
      if (comp[i] && i != ilow && i != ihigh && adj2[i].size() <= 2) todo.insert(i);
    while (!todo.empty()) {
      const int i = *todo.begin();
      todo.erase(todo.begin());
      if (adj2[i].empty() || adj2[i].size() > 2) continue;
      Eliminated g{i, -1, -1, {0.0, 0.0}, {0.0, 0.0}};
      auto it = adj2[i].begin();
      g.p = it->first, g.yp = it->second;
      if (adj2[i].size() == 2) ++it, g.q = it->first, g.yq = it->second;
      if (g.q >= 0 && g.yp + g.yq == cplx(0.0, 0.0)) continue;  // left to the LU
      adj2[g.p].erase(i);
      if (g.q >= 0) {
        adj2[g.q].erase(i);
        const cplx y = g.yp * g.yq / (g.yp + g.yq);
        adj2[g.p][g.q] += y;
        adj2[g.q][g.p] += y;
      }
      adj2[i].clear();
      gone.push_back(g);
      for (int k : {g.p, g.q})
        if (k >= 0 && k != ilow && k != ihigh && adj2[k].size() <= 2) todo.insert(k);
    }
  }
  std::vector<char> solved(comp);
  for (const Eliminated &g : gone) solved[g.node] = 0;

  // Unknowns: the remaining nodes but the grounded low electrode.
  std::vector<int> row(n, -1);
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (solved[i] && i != ilow) row[i] = m++;
  s.unknowns = m;
  s.eliminated = static_cast<int>(gone.size());
  std::vector<cplx> diag(m, cplx(0.0, 0.0));
  std::vector<Eigen::Triplet<cplx>> trip;
  for (int i = 0; i < n; ++i) {
    if (row[i] < 0) continue;
    for (const auto &[j, y] : adj2[i]) {
      diag[row[i]] += y;
      if (row[j] >= 0) trip.emplace_back(row[i], row[j], -y);
    }
  }
  // Symmetric diagonal scaling D Y D with D = |Y_ii|^-1/2: admittances over many decades
  // (a metallic contact next to a film capacitance) leave a matrix of unit diagonal.
  std::vector<double> d(m);
  for (int i = 0; i < m; ++i)
    d[i] = diag[i] == cplx(0.0, 0.0) ? 1.0 : 1.0 / std::sqrt(std::abs(diag[i]));
  for (auto &t : trip)
    t = Eigen::Triplet<cplx>(t.row(), t.col(), t.value() * d[t.row()] * d[t.col()]);
  for (int i = 0; i < m; ++i) trip.emplace_back(i, i, diag[i] * d[i] * d[i]);
  Eigen::SparseMatrix<cplx> a(m, m);
  a.setFromTriplets(trip.begin(), trip.end());
  a.makeCompressed();
  // Y is complex symmetric (Y^T = Y), not Hermitian (Y^H != Y as soon as C > 0): Eigen's
  // SimplicialLDLT/LLT and CG assume a self-adjoint matrix (they conjugate the lower
  // triangle) and would solve another system. SparseLU makes no symmetry assumption; its
  // partial pivoting also covers the indefinite real part a capacitive network gives.
  Eigen::SparseLU<Eigen::SparseMatrix<cplx>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("solve_complex_network: the sparse LU factorization failed");
  Eigen::VectorXcd b = Eigen::VectorXcd::Zero(m);
  b[row[ihigh]] = current * d[row[ihigh]];
  const Eigen::VectorXcd x = lu.solve(b);
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("solve_complex_network: the sparse LU solve failed");
  for (int i = 0; i < n; ++i)
    if (row[i] >= 0) s.potentials[i] = x[row[i]] * d[row[i]];
  // The eliminated nodes, last first: v = (yp vp + yq vq) / (yp + yq), or vp when dangling.
  for (auto g = gone.rbegin(); g != gone.rend(); ++g)
    s.potentials[g->node] =
        g->q < 0 ? s.potentials[g->p]
                 : (g->yp * s.potentials[g->p] + g->yq * s.potentials[g->q]) / (g->yp + g->yq);
  s.z = s.potentials[ihigh] / current;
  return s;
}

}  // namespace ohmdem
