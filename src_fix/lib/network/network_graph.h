// SPDX-License-Identifier: GPL-2.0-or-later
// The graph of a conduction network (internal to network/): edges in canonical order, node
// indices, adjacency lists with parallel edges merged, the component of an electrode.
#ifndef OHMDEM_NETWORK_GRAPH_H
#define OHMDEM_NETWORK_GRAPH_H

#include <vector>

#include "network/conduction_network.h"

namespace ohmdem::net {

struct RawEdge {
  NodeKey a, b;  // a < b
  double g;
};

// Total order on (a, b, g): parallel edges are then summed in the same order whatever the
// insertion order, which is what makes R bitwise reproducible.
bool canonical_less(const RawEdge &x, const RawEdge &y);

struct Link {
  int to;
  double g;
};
using Adjacency = std::vector<std::vector<Link>>;

void remove_link(std::vector<Link> &list, int to);
// Adds g to the link a-b (both directions), creating it if needed.
void add_link(Adjacency &adj, int a, int b, double g);

// Sorts `raw` canonically; keys = its node keys, sorted and unique; ea[k], eb[k] = indices in
// keys of the ends of raw[k].
void index_nodes(std::vector<RawEdge> &raw, std::vector<NodeKey> &keys, std::vector<int> &ea,
                 std::vector<int> &eb);
// Adjacency lists of n nodes with parallel edges merged (raw sorted: each pair contiguous).
Adjacency merged_adjacency(const std::vector<RawEdge> &raw, const std::vector<int> &ea,
                           const std::vector<int> &eb, int n);
// Marks (comp[i] = 1) the nodes reachable from `start`; returns how many.
int mark_component(const Adjacency &adj, int start, std::vector<char> &comp);

}  // namespace ohmdem::net

#endif
