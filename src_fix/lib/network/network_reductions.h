// SPDX-License-Identifier: GPL-2.0-or-later
// Exact reductions of a conduction network (internal to network/): Kirchhoff's series and
// dangling-node rules before a solve, and the subtraction-free Kron elimination used when a
// factorization cannot reach its accuracy. doc/methods/conduction_network.md.
#ifndef OHMDEM_NETWORK_REDUCTIONS_H
#define OHMDEM_NETWORK_REDUCTIONS_H

#include <vector>

#include "network/network_graph.h"

namespace ohmdem::net {

// A node removed before the solve, and how to get its potential back afterwards.
struct Elimination {
  int node;
  int a, b;  // neighbours (b < 0: dangling node, it carries no current: V = V_a)
  double ga, gb;
};

// A dangling node (one neighbour) carries no current; a node with two neighbours is two
// conductances in series. Electrodes ih, il are never removed.
void reduce(Adjacency &adj, std::vector<char> &alive, std::vector<Elimination> &elim, int ih,
            int il);
// Potentials of the eliminated nodes, last eliminated first (its neighbours are known).
void eliminated_potentials(const std::vector<Elimination> &elim, std::vector<double> &v);

// Kron reduction (the star-mesh transform of reduce() for any degree): node k with total
// conductance D_k adds g_ik g_jk / D_k between every pair of its neighbours. Only positive
// terms, so every conductance keeps full relative accuracy however wide their spread, where
// an LDL^T of the assembled matrix rounds small conductances away in the pivots (and can meet
// a zero pivot). `order` lists the nodes to eliminate, never the electrodes. Returns the
// conductance left between ih and il; the records give the potentials back (kron_potentials).
struct KronRecord {
  int node;
  double total;
  std::vector<Link> links;
};
double kron_eliminate(Adjacency &adj, const std::vector<int> &order, int ih, int il,
                      std::vector<KronRecord> &records);
// Potentials of Kron-eliminated nodes, last first: V_k = sum g_kj V_j / D_k, a weighted mean.
void kron_potentials(const std::vector<KronRecord> &records, std::vector<double> &v);

}  // namespace ohmdem::net

#endif
