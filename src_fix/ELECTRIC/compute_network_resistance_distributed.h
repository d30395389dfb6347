// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance, the distributed path (`solver distributed`, or
   `solver auto` with several processes and a large group): each process builds the part of
   the network of the particles it owns and the rows of those nodes go to a hypre matrix on
   the simulation's communicator (network/distributed_solve.h); no process gathers the
   whole network. Adapter code (LIGGGHTS types); doc/compute_network_resistance.md, "Solve".
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_NETWORK_RESISTANCE_DISTRIBUTED_H
#define LMP_COMPUTE_NETWORK_RESISTANCE_DISTRIBUTED_H

#include <cstdint>
#include <memory>
#include <vector>

#include "ELECTRIC/contact_set.h"
#include "conduction/conduction_model.h"
#include "conduction/network_builder.h"
#include "network/conduction_network.h"
#include "network/distributed_solve.h"
#include "pointers.h"

namespace LAMMPS_NS {


class NetworkResistanceDistributed : protected Pointers {
 public:
  struct Setup {
    const ohmdem::ConductionModel *model;
    const std::vector<double> *gamma_type;  // S/m per atom type, 1-based
    const std::vector<double> *gamma_race;  // S/m per race
    int groupbit, high_bit, low_bit;        // electrode groups' bits (0 for a race electrode)
    ohmdem::NodeKey high, low;              // electrode nodes
  };
  struct Result {
    ohmdem::DistributedSolution solution;
    long long contacts = 0;  // conducting contacts, over all processes
  };

  explicit NetworkResistanceDistributed(LAMMPS *lmp);
  ~NetworkResistanceDistributed();
  // Collective.
  Result solve(ContactSet &contacts, const Setup &setup, double current);
  // Collective, after solve() on the same step (only when something reads them: the
  // potentials of other processes' nodes are asked for): phi[i] (V) for the local particles,
  // the mean potential of their contact nodes, as the gathered path gives it.
  void potentials(int groupbit, double *phi);
  double memory_usage() const;

 private:
  void route(ContactSet &contacts, const Setup &setup);

  std::unique_ptr<ohmdem::DistributedNetworkSolver> solver_;
  // This process's scene: its particles, the partners of their contacts, every contact of
  // its particles (a contact between processes on both).
  std::vector<std::int64_t> owned_tags_;
  std::vector<ohmdem::ParticleRecord> particles_;
  std::vector<ohmdem::ContactRecord> contacts_;
  std::vector<char> recorded_;  // per local and ghost atom: already in particles_
  std::vector<ContactSet::Contact> collected_;  // this process's contacts (memory kept)
  ohmdem::NetworkBuild built_;
  std::vector<ohmdem::NodeKey> owned_nodes_;
  std::vector<ohmdem::DistributedEdge> share_;
};

}  // namespace LAMMPS_NS

#endif
