// SPDX-License-Identifier: GPL-2.0-or-later
// Writers for a ConductionNetwork: a SPICE netlist (independent check with a circuit
// simulator, e.g. `ngspice -b`) and legacy-VTK line sets (ParaView). Output is a function of
// the network content only, never of the insertion order.
#ifndef OHMDEM_NETWORK_EXPORT_H
#define OHMDEM_NETWORK_EXPORT_H

#include <array>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "network/complex_network.h"
#include "network/conduction_network.h"

namespace ohmdem {

// --- SPICE -------------------------------------------------------------------------------
// One `R` element per added conductance (value 1/g, 17 significant digits), in the canonical
// edge order. The low electrode is node `0`, the high electrode `ehigh`, any other node
// `n<key>`. The current source `I1 0 ehigh DC <I>` injects I into `ehigh`; the deck ends with
// `.op` and `.end`, so V(ehigh) = R * I. Conductances outside the component holding the high
// electrode are written as comment lines: SPICE rejects floating nodes (singular matrix).
// Needs the electrodes to be set (throws std::invalid_argument otherwise); no solve needed.
struct SpiceOptions {
  std::string title = "ohmdem conduction network";
};
std::string spice_node_name(const ConductionNetwork &net, NodeKey key);
void write_spice_netlist(std::ostream &os, const ConductionNetwork &net, double current,
                         const SpiceOptions &options = {});

// The AC netlist of a complex admittance network (complex_network.h) at angular frequency
// omega: each edge y = G + j omega C as `R` (1/G, left out when G = 0) and `C` (Im y / omega,
// left out when 0) between the same nodes, 17 significant digits, edges in canonical order
// (a < b, then y). The low electrode is `0`, the high `ehigh`, any other node `name(key)`.
// `I1 0 ehigh AC <I>` and `.ac lin 1 f f` (f = omega / 2 pi): ngspice's AC analysis gives
// V(ehigh) = Z I. `.option rshunt=1e30` ties every node to ground through 1e30 ohm, the DC
// path SPICE's operating point needs for a node joined by capacitors only; it changes Z by
// |Z| / 1e30 relatively. Edges outside the high electrode's component are comment lines.
using SpiceNodeNameFn = std::function<std::string(NodeKey)>;
void write_spice_ac_netlist(std::ostream &os, std::vector<ComplexEdge> edges, NodeKey high,
                            NodeKey low, double current, double omega, const SpiceNodeNameFn &name,
                            const SpiceOptions &options = {});

// --- VTK ---------------------------------------------------------------------------------
// ASCII legacy VTK, DATASET POLYDATA: points with point data `potential` (V) and
// `connected`, one line cell per edge with cell data `conductance` (S), `current` (A, from
// the first to the second point), `connected`, and any caller-supplied per-edge scalars.
// Potentials and currents are those of the last solve (0 if none).
struct VtkEdge {
  NodeKey a, b;
  double conductance;
  std::array<double, 3> pa, pb;  // where to draw the two ends
  std::vector<double> scalars;   // one value per VtkOptions::edge_scalar_names
};
struct VtkOptions {
  std::string title = "ohmdem conduction network";
  std::vector<std::string> edge_scalar_names;  // e.g. {"area", "masked"}
};

// Explicit edges: the caller draws each edge between its own two points. Use it when a node
// has no single position: an electrode is one node but touches at many points (a race), and
// in the bearing every ball's conductance joins the two electrode nodes directly. Points
// with the same (key, position) are merged. Edges are written sorted (a, b, g, positions,
// scalars), so the file does not depend on the order of `edges`. Throws
// std::invalid_argument if an edge has the wrong number of scalars.
void write_vtk_network(std::ostream &os, const ConductionNetwork &net, std::vector<VtkEdge> edges,
                       const VtkOptions &options = {});

// The network's own edges (net.edges(), canonical order), one point per node placed by
// `position`, which returns false for a node it cannot place (its edges are then skipped).
// `edge_scalars`, if set, fills the caller's per-edge scalars of edge (a, b, g).
using NodePositionFn = std::function<bool(NodeKey, std::array<double, 3> &)>;
using EdgeScalarsFn = std::function<void(const NetworkEdge &, std::vector<double> &)>;
void write_vtk_network(std::ostream &os, const ConductionNetwork &net,
                       const NodePositionFn &position, const VtkOptions &options = {},
                       const EdgeScalarsFn &edge_scalars = nullptr);

}  // namespace ohmdem

#endif
