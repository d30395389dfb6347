// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: one way of evaluating the conduction model on this step's
// contacts (LAMMPS' sub-model idea: the compute parses, checks, chooses and forwards; a path
// evaluates). Three paths implement it, each in its own file:
//   resistance_path_closed_form  a bearing: one resistor per ball, inline, no matrix;
//   resistance_path_gathered     the whole network gathered on every process and solved;
//   resistance_path_distributed  each process's share of the network, one hypre solve.
// The compute makes one virtual call per evaluation; the per-ball loops stay inside a path.
// doc/compute_network_resistance.md, "Solve". Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_RESISTANCE_PATH_H
#define OHMDEM_STYLE_RESISTANCE_PATH_H

#include <cstdint>
#include <vector>

#include "conduction/contact_flows.h"

namespace LAMMPS_NS {

// What an evaluation gives the compute's global outputs.
struct PathResult {
  double resistance = 0;  // Ohm, +inf without a conducting path
  int contacts = 0;       // conducting contacts
  int dropped = 0;        // floating nodes dropped
  int iterations = 0;     // of an iterative solver, 0 otherwise
  double residual = 0;    // its relative residual
  // contacts joining the two electrodes directly where the model gives them no resistance
  // (NetworkBuild::electrode_shorts), and the first one's atoms
  int shorts = 0;
  std::int64_t short_tags[2] = {0, 0};
};

class ResistancePath {
 public:
  virtual ~ResistancePath() = default;
  // Collective. Evaluates this step and fills phi[i] (V) for the local atoms, unless the path
  // leaves them to potentials(). Returns false, on every process alike, when the scene is not
  // one this path evaluates (then nothing is reported and the compute asks another path).
  virtual bool evaluate(double *phi, PathResult &result) = 0;
  // Collective, after evaluate() on the same step, only when something reads the per-atom
  // potentials: the paths that leave them (the distributed one) fill phi here.
  virtual void potentials(double * /*phi*/) {}
  // The local array's rows of the last evaluation, for the contacts whose atom this process
  // owns (appended to `rows`; any order: the caller sorts).
  virtual void contact_flows(std::vector<ohmdem::ContactFlow> &rows) = 0;
  // Bytes held for the solve that LIGGGHTS' memory report counts (the distributed solver's
  // matrix and scene; the others' per-step buffers are not counted).
  virtual double memory_usage() const { return 0.0; }
};

}  // namespace LAMMPS_NS

#endif
