// SPDX-License-Identifier: GPL-2.0-or-later
// A network of complex admittances Y = G + j omega C (AC steady state, phasors): the nodal
// system Y v = i with the low electrode grounded and a current I injected into the high
// electrode, solved by a sparse LU. The impedance Z = v(high) / I. Plain C++ (Eigen).
// Used by compute network/resistance with a lubricant (doc/methods/lubricated_contact.md).
#ifndef OHMDEM_NETWORK_COMPLEX_NETWORK_H
#define OHMDEM_NETWORK_COMPLEX_NETWORK_H

#include <complex>
#include <vector>

#include "network/conduction_network.h"

namespace ohmdem {

struct ComplexEdge {
  NodeKey a, b;
  std::complex<double> y;  // admittance (S); an edge with y = 0 connects nothing
};

struct ComplexSolution {
  // Z = v(high) / I (ohm); (+inf, 0) when no edge path joins the electrodes.
  std::complex<double> z{0.0, 0.0};
  bool connected = false;  // a path of non-zero admittances joins the electrodes
  int unknowns = 0;        // nodes left to the LU (the low electrode's component, but itself)
  int eliminated = 0;      // dangling and series nodes eliminated before it
  // Every node key (sorted) and its potential (V); 0 outside the low electrode's component.
  std::vector<NodeKey> keys;
  std::vector<std::complex<double>> potentials;
  std::vector<char> in_component;
  // The potential of a key (0 for a key not in the network).
  std::complex<double> potential(NodeKey key) const;
};

struct ComplexOptions {
  // Eliminate dangling and degree-2 nodes exactly before the LU (as ConductionNetwork's
  // reduce_series): a ball between two races is two admittances in series.
  bool reduce_series = true;
};

// The edges may come in any order and hold parallel edges (summed in a canonical order: the
// result does not depend on the order of `edges`). Throws std::invalid_argument for
// high == low, a self loop, a non-finite admittance or a current <= 0, std::runtime_error if
// the factorization fails (a singular system: not possible with finite non-zero edges).
ComplexSolution solve_complex_network(std::vector<ComplexEdge> edges, NodeKey high, NodeKey low,
                                      double current, const ComplexOptions &options = {});

}  // namespace ohmdem

#endif
