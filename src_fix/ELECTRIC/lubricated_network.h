// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant: the general network of the bearing in complex
// arithmetic (keyword closedform no) and its AC netlist. The contact records of all processes
// are gathered in tag order (on every process: each solves the same system and gets the same
// bits); nodes are the two electrode races and one per ball, edges the contacts' Y = G + j
// omega C. The solve is network/complex_network.*. Adapter code (MPI, no LIGGGHTS type).
#ifndef OHMDEM_STYLE_LUBRICATED_NETWORK_H
#define OHMDEM_STYLE_LUBRICATED_NETWORK_H

#include <mpi.h>

#include <complex>
#include <iosfwd>
#include <vector>

#include "common/ordered_reduce.h"
#include "network/complex_network.h"

namespace LAMMPS_NS {

struct LubricatedContact;

class LubricatedNetwork {
 public:
  // Collective: the records of all processes, in tag order (then race side).
  void gather(const std::vector<LubricatedContact> &local, MPI_Comm comm);
  // Z = V(high) / I of the gathered network; (+inf, 0) without a path.
  std::complex<double> solve(double current) const;
  // The AC netlist of the gathered network (network_export.h): ball nodes b<tag>.
  void write_netlist(std::ostream &os, double current, double omega) const;
  const std::vector<ohmdem::ComplexEdge> &edges() const { return edges_; }

 private:
  std::vector<ohmdem::TaggedValues<3>> local_;  // side, Re Y, Im Y
  ohmdem::OrderedGather<3> gather_;
  std::vector<ohmdem::ComplexEdge> edges_;  // of the last gather, in tag order
};

}  // namespace LAMMPS_NS

#endif
