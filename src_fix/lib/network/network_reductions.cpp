// SPDX-License-Identifier: GPL-2.0-or-later
// Exact reductions of a conduction network; see network_reductions.h.
#include "network/network_reductions.h"

#include <algorithm>
#include <utility>

namespace ohmdem::net {

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

void eliminated_potentials(const std::vector<Elimination> &elim, std::vector<double> &v)
{
  for (auto it = elim.rbegin(); it != elim.rend(); ++it) {
    if (it->a < 0)
      v[it->node] = 0.0;
    else if (it->b < 0)
      v[it->node] = v[it->a];
    else
      v[it->node] = (it->ga * v[it->a] + it->gb * v[it->b]) / (it->ga + it->gb);
  }
}

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

void kron_potentials(const std::vector<KronRecord> &records, std::vector<double> &v)
{
  for (auto it = records.rbegin(); it != records.rend(); ++it) {
    double sum = 0.0;
    for (const Link &l : it->links) sum += l.g * v[l.to];
    v[it->node] = sum / it->total;
  }
}

}  // namespace ohmdem::net
