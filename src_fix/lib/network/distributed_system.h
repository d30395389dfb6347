// SPDX-License-Identifier: GPL-2.0-or-later
// The grounded Kirchhoff system of a conduction network spread over MPI ranks, each rank
// holding the rows of the nodes it owns (no rank holds the whole network). Used by the
// distributed solve (distributed_solve.h); plain C++ with MPI, no LIGGGHTS types.
//
// Input per rank: the keys of the nodes it owns (unique over all ranks) and its share of the
// conductances (each edge on exactly one rank, endpoints owned anywhere). The two electrode
// keys are Dirichlet nodes (high 1 V, low 0 V) eliminated into the right-hand side; they own
// no row. Numbering: this rank's rows are a contiguous range (prefix sum of the owned counts
// over the ranks, in rank order), its keys sorted inside it; the rows of other ranks' nodes
// come from a KeyDirectory. Each edge is sent to the owners of both its ends, who sort their
// entries before adding them: a row's numbers do not depend on message order.
//
// Floating components (no electrode reached, e.g. a cluster of particles touching nothing):
// their Laplacian block is singular. They are found by a union-find on each rank's rows
// followed by a union-find of the per-rank components on rank 0 (the cross-rank edges only),
// and their rows become identity rows (potential 0), as the serial solver drops them.
#ifndef OHMDEM_DISTRIBUTED_SYSTEM_H
#define OHMDEM_DISTRIBUTED_SYSTEM_H

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "network/conduction_network.h"
#include "network/key_directory.h"

namespace ohmdem {

struct DistributedEdge {
  NodeKey a, b;
  double g;  // S; g <= 0 or non-finite is ignored (counted), a == b too
};

// A conductance as one row sees it (col: kHigh / kLow in distributed_system.cpp for an
// electrode).
struct DistributedEntry {
  int row, col;  // global
  double g;
};

// The assembly's buffers, kept from one assembly to the next: their memory is reused, not
// allocated again (fresh pages cost a fault each, which dominated repeated assemblies).
struct DistributedScratch {
  std::vector<int> ends;                               // rows of the edges' ends
  std::vector<NodeKey> need;                           // ends owned elsewhere
  std::vector<DistributedEntry> sorted;                // this rank's rows' entries, by row
  std::vector<std::vector<DistributedEntry>> outgoing;  // entries of other ranks' rows
  std::vector<std::size_t> bucket;                     // per row: its first entry
};

struct DistributedSystem {
  int first_row = 0;           // global index of this rank's first row
  int total_rows = 0;          // over all ranks
  std::vector<NodeKey> keys;   // owned keys, sorted: row first_row + i
  std::vector<int> row_start;  // compressed rows: global columns, sorted, diagonal included
  std::vector<int> columns;
  std::vector<double> values;
  std::vector<double> rhs;      // per row: conductance to the high electrode (V_high = 1)
  std::vector<double> to_low;   // per row: conductance to the low electrode
  std::vector<int> starts;      // first row of every rank, and total_rows at the end
  std::vector<int> ghosts;      // columns owned elsewhere, sorted
  KeyDirectory directory;       // key -> global row, for every owned key
  std::vector<char> floating;   // per row: in a component that reaches no electrode
  double direct = 0;            // conductance high-low summed over all ranks (rank order)
  bool connected = false;       // some path joins high and low (all ranks agree)
  long long floating_rows = 0;  // over all ranks
  long long edges = 0;          // accepted edges over all ranks
  long long ignored = 0;        // over all ranks: g <= 0 or non-finite
  long long self_loops = 0;     // over all ranks: a == b
  DistributedScratch scratch;
};

// Collective over comm. Throws std::invalid_argument if an edge names a node that no rank
// owns (a caller bug), std::length_error past 2^31 - 1 rows (hypre's 32-bit indices).
void assemble_distributed(MPI_Comm comm, std::vector<NodeKey> owned,
                          const std::vector<DistributedEdge> &edges, NodeKey high, NodeKey low,
                          DistributedSystem &out);

// Collective: the values at `rows` (global, sorted, unique) given this rank's row values.
std::vector<double> values_at_rows(MPI_Comm comm, const DistributedSystem &sys,
                                   const std::vector<double> &mine, const std::vector<int> &rows);

// Sums one double per rank in rank order: bitwise the same for a fixed number of ranks.
double ordered_rank_sum(double mine, MPI_Comm comm);

}  // namespace ohmdem

#endif
