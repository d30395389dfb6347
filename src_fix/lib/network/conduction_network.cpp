// SPDX-License-Identifier: GPL-2.0-or-later
// The conduction network's facade: edges in, R and potentials out. The graph, the exact
// reductions and the solve strategy are in network_graph.*, network_reductions.* and
// network_solve.*. Numerics (why each step is there): doc/methods/conduction_network.md.
#include "network/conduction_network.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "network/network_graph.h"
#include "network/network_reductions.h"
#include "network/network_solve.h"

namespace ohmdem {

using net::Adjacency;
using net::Link;

class ConductionNetwork::Impl {
 public:
  std::vector<net::RawEdge> raw;
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
  net::WarmStart warm;  // potentials per unit current of the last connected solve
  net::SystemSolver system;

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
  bool connect(Adjacency &adj, int ih, int il, NetworkSolution &s);
  void solve_connected(Adjacency &adj, int ih, int il, double current, SolverKind kind,
                       NetworkSolution &s);
  void keep_warm_start(double current);
};

void ConductionNetwork::Impl::prepare()
{
  if (prepared) return;
  net::index_nodes(raw, keys, ea, eb);
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
  Adjacency adj;
  if (ih < 0 || il < 0 || !connect(adj, ih, il, s)) {
    s.resistance = s.voltage_drop = std::numeric_limits<double>::infinity();
    s.floating_nodes_dropped = n;
    return last = s;
  }
  solve_connected(adj, ih, il, current, kind, s);
  keep_warm_start(current);
  return last = s;
}

// The graph with parallel edges merged, restricted to the component holding the high
// electrode (only it can carry current); false if the low electrode is not in it.
bool ConductionNetwork::Impl::connect(Adjacency &adj, int ih, int il, NetworkSolution &s)
{
  const int n = static_cast<int>(keys.size());
  adj = net::merged_adjacency(raw, ea, eb, n);
  const int reached = net::mark_component(adj, ih, comp);
  if (!comp[il]) {
    std::fill(comp.begin(), comp.end(), 0);
    return false;
  }
  s.connected = true;
  s.floating_nodes_dropped = n - reached;
  for (std::size_t k = 0; k < raw.size(); ++k) s.conducting_edges += comp[ea[k]];
  for (int i = 0; i < n; ++i)
    if (!comp[i]) adj[i].clear();
  return true;
}

// Exact reductions, then a closed form or the linear system, then the potentials of the
// eliminated nodes.
void ConductionNetwork::Impl::solve_connected(Adjacency &adj, int ih, int il, double current,
                                              SolverKind kind, NetworkSolution &s)
{
  const int n = static_cast<int>(keys.size());
  std::vector<char> alive(comp);
  std::vector<net::Elimination> elim;
  if (opt.reduce_series) net::reduce(adj, alive, elim, ih, il);
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
    system.solve({adj, unk, ih, il, current, keys}, kind, opt, warm, volt, s);
  }
  s.voltage_drop = s.resistance * current;
  net::eliminated_potentials(elim, volt);
}

void ConductionNetwork::Impl::keep_warm_start(double current)
{
  warm.keys.clear();
  warm.values.clear();
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (comp[i]) {
      warm.keys.push_back(keys[i]);
      warm.values.push_back(volt[i] / current);
    }
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
  impl_->warm.keys.clear();
  impl_->warm.values.clear();
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

NetworkEdge ConductionNetwork::added_edge(std::size_t k) const
{
  const net::RawEdge &e = impl_->raw[k];
  return {e.a, e.b, e.g, 0.0, false};
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
