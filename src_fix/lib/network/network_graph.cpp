// SPDX-License-Identifier: GPL-2.0-or-later
// The graph of a conduction network; see network_graph.h.
#include "network/network_graph.h"

#include <algorithm>
#include <utility>

namespace ohmdem::net {

bool canonical_less(const RawEdge &x, const RawEdge &y)
{
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  return x.g < y.g;
}

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

void index_nodes(std::vector<RawEdge> &raw, std::vector<NodeKey> &keys, std::vector<int> &ea,
                 std::vector<int> &eb)
{
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
}

Adjacency merged_adjacency(const std::vector<RawEdge> &raw, const std::vector<int> &ea,
                           const std::vector<int> &eb, int n)
{
  Adjacency adj(n);
  for (std::size_t k = 0; k < raw.size();) {
    double g = 0.0;
    std::size_t j = k;
    for (; j < raw.size() && raw[j].a == raw[k].a && raw[j].b == raw[k].b; ++j) g += raw[j].g;
    adj[ea[k]].push_back({eb[k], g});
    adj[eb[k]].push_back({ea[k], g});
    k = j;
  }
  return adj;
}

int mark_component(const Adjacency &adj, int start, std::vector<char> &comp)
{
  std::vector<int> queue{start};
  comp[start] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (const Link &l : adj[queue[q]])
      if (!comp[l.to]) {
        comp[l.to] = 1;
        queue.push_back(l.to);
      }
  return static_cast<int>(queue.size());
}

}  // namespace ohmdem::net
