// SPDX-License-Identifier: GPL-2.0-or-later
// Shared helpers for the network tests: random networks, an independent dense reference
// solve (long double, full-pivot LU), and an ngspice runner.
#ifndef OHMDEM_TESTS_NETWORK_TEST_UTILS_H
#define OHMDEM_TESTS_NETWORK_TEST_UTILS_H

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "network/conduction_network.h"

namespace ohmdem_test {

using ohmdem::NodeKey;

struct Edge {
  NodeKey a, b;
  double g;
};

struct RandomNetwork {
  std::vector<NodeKey> keys;  // keys[0] = high electrode, keys[1] = low electrode
  std::vector<Edge> edges;
};

// Connected random graph: a random spanning tree plus `extra` random chords, conductances
// log-uniform in [10^lg_min, 10^lg_max]. Keys are scrambled 64-bit numbers, unrelated to the
// insertion order.
RandomNetwork random_network(int nodes, int extra, double lg_min, double lg_max,
                             std::uint64_t seed);

// Packing-like network: particles on a jittered 2D (nz = 1) or 3D lattice, each touching its
// lattice neighbours; nodes are the contacts, each particle joins all of its contacts with
// eq. 1 conductances (a clique per particle). The bottom layer touches the low electrode,
// the top layer the high one.
RandomNetwork packing_network(int nx, int ny, int nz, std::uint64_t seed);

// Every conductance multiplied by 10^U(-decades/2, decades/2): a wide spread on top of the
// structure (ill-conditioned systems).
RandomNetwork widened(RandomNetwork net, double decades, std::uint64_t seed);

void add_all(ohmdem::ConductionNetwork &net, const std::vector<Edge> &edges);
// A fresh network with options o and the electrodes keys[0], keys[1]: all edges, one solve.
ohmdem::NetworkSolution solve_with(const RandomNetwork &rn, ohmdem::SolverOptions o,
                                   double current = 0.1);
// The network of the next "time step": every conductance times 1 + U(-amplitude, amplitude).
RandomNetwork perturbed(const RandomNetwork &rn, double amplitude, std::uint64_t seed);
// Default options but for the solver kind.
ohmdem::SolverOptions kind(ohmdem::SolverKind k);
// Random networks checked against the dense reference by every solver's test: node count,
// extra edges, conductances 10^U(lg_min, lg_max) (random_network, seed 7).
struct DenseCase {
  int nodes, extra;
  double lg_min, lg_max;
};
inline const DenseCase kDenseCases[] = {{400, 800, -1, 1}, {400, 800, -6, 6}, {300, 300, -3, 3}};

// R between keys[0] and keys[1] from the dense grounded Laplacian, long double full-pivot
// LU: independent of the library's reduction, scaling and sparse solvers.
long double dense_resistance(const RandomNetwork &net);

// The same R by a dense subtraction-free Kron elimination in long double (node k adds
// g_ik g_jk / D_k between its neighbours): accurate to ~1e-18 however wide the spread of
// conductances, where the LU above loses digits beyond ~16 decades.
long double dense_kron_resistance(const RandomNetwork &net);

bool have_ngspice();
// Writes the netlist of `net` (solved or not) to a temporary file, runs `ngspice -b` with an
// ASCII raw file and returns V(ehigh); NaN on failure (the log is appended to `error`).
double ngspice_ehigh_voltage(const ohmdem::ConductionNetwork &net, double current,
                             const std::string &name, std::string &error);

}  // namespace ohmdem_test

namespace ohmdem {
// Readable enum values in GoogleTest failure messages.
inline void PrintTo(SolveMethod m, std::ostream *os)
{
  *os << to_string(m);
}
}  // namespace ohmdem

#endif
