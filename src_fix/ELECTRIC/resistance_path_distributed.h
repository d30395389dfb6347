// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance, the distributed path (`solver distributed`, or
   `solver auto` with several processes and a large group): each process builds the part of
   the network of the particles it owns and the rows of those nodes go to a hypre matrix on
   the simulation's communicator (network/distributed_solve.h); no process gathers the
   whole network (a path of resistance_path.h). Adapter code (LIGGGHTS types);
doc/compute_network_resistance.md, "Solve".
------------------------------------------------------------------------- */

#ifndef OHMDEM_STYLE_RESISTANCE_PATH_DISTRIBUTED_H
#define OHMDEM_STYLE_RESISTANCE_PATH_DISTRIBUTED_H

#include <cstdint>
#include <memory>
#include <vector>

#include "ELECTRIC/resistance_context.h"
#include "ELECTRIC/resistance_path.h"
#include "conduction/network_builder.h"
#include "network/conduction_network.h"
#include "network/distributed_solve.h"
#include "pointers.h"

namespace LAMMPS_NS {

class DistributedNetworkPath : public ResistancePath, protected Pointers {
 public:
  // `context` outlives the path.
  DistributedNetworkPath(LAMMPS *lmp, const ResistanceContext &context);
  ~DistributedNetworkPath() override;
  bool evaluate(double *phi, PathResult &result) override;
  // Only when something reads them (the potentials of other processes' nodes are asked
  // for): phi[i] (V) for the local particles, the mean potential of their contact nodes, as
  // the gathered path gives it.
  void potentials(double *phi) override;
  // An error: the rows need every node potential, and each stays on its owner.
  void contact_flows(std::vector<ohmdem::ContactFlow> &rows) override;
  double memory_usage() const override;

 private:
  void route();

  const ResistanceContext &context_;
  std::unique_ptr<ohmdem::DistributedNetworkSolver> solver_;
  // This process's scene: its particles, the partners of their contacts, every contact of
  // its particles (a contact between processes on both).
  std::vector<std::int64_t> owned_tags_;
  std::vector<ohmdem::ParticleRecord> particles_;
  std::vector<ohmdem::ContactRecord> contacts_;
  std::vector<char> recorded_;                    // per local and ghost atom: already in particles_
  std::vector<ohmdem::ContactRecord> collected_;  // this process's contacts (memory kept)
  std::vector<double> gamma_race_;
  ohmdem::NetworkBuild built_;
  std::vector<ohmdem::NodeKey> owned_nodes_;
  std::vector<ohmdem::DistributedEdge> share_;
};

}  // namespace LAMMPS_NS

#endif
