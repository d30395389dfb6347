// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance: the electrical resistance of a
   contact network between two electrodes (paper eq. 1, Kirchhoff + Ohm).
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

// clang-format off
ComputeStyle(network/resistance,ComputeNetworkResistance)
// clang-format on

#else

#ifndef LMP_COMPUTE_NETWORK_RESISTANCE_H
#define LMP_COMPUTE_NETWORK_RESISTANCE_H

#include <memory>
#include <string>

#include "ELECTRIC/lubricated_bearing.h"
#include "ELECTRIC/lubricated_vtk.h"
#include "ELECTRIC/resistance_context.h"
#include "compute.h"

namespace LAMMPS_NS {

class ClosedFormPath;
class ContactFlowArray;
class ContactSet;
class DistributedNetworkPath;
class GatheredNetworkPath;
class NetworkExports;
class ResistancePath;
struct PathResult;

class ComputeNetworkResistance : public Compute {
 public:
  ComputeNetworkResistance(class LAMMPS *, int &iarg, int, char **);
  ~ComputeNetworkResistance() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  void compute_local() override;
  double memory_usage() override;

 private:
  void parse(int narg, char **arg);
  void resolve(const char *keyword, Electrode &e);
  void read_conductivities();
  void choose_paths();  // init(): the closed form if it may apply, the general network
  void evaluate();      // once per time step, by one of the paths
  void report(const PathResult &r);

  // Keywords (the electrodes, model and current are in context_).
  int solver_ = 0;                   // ohmdem::SolverKind
  bool multigrid_ = false;           // solver amg: CG preconditioned by algebraic multigrid
  bool distributed_solver_ = false;  // solver distributed
  bool area_exact_ = false;
  int pair_mode_ = -1;         // -1 auto (use the granular pair style if there is one), 0 no, 1 yes
  std::string netlist_, vtk_;  // a `*` stands for the step (vtk_series.h)
  bigint every_ = 0;           // exports on steps that are multiples of every_ (0: each evaluation)
  bool closed_form_ = true;    // keyword closedform: use the two-race closed form when it applies

  ResistanceContext context_;  // what the paths read
  std::unique_ptr<ContactSet> contacts_;
  std::unique_ptr<NetworkExports> exports_;
  // The paths (resistance_path.h). Kept from run to run: the gathered network and the
  // distributed solver warm-start from their last solve.
  std::unique_ptr<ClosedFormPath> closed_form_path_;  // null when it cannot apply in this run
  std::unique_ptr<GatheredNetworkPath> gathered_;
  std::unique_ptr<DistributedNetworkPath> distributed_;  // made when first chosen
  ResistancePath *network_path_ = nullptr;               // gathered or distributed, this run
  ResistancePath *last_path_ = nullptr;                  // the path of the last evaluation
  std::unique_ptr<ContactFlowArray> local_;              // the local array
  // Keyword lubricant (lubricated_bearing.h): null with `lubricant none`, and then nothing of
  // it runs and the vector keeps its 8 values.
  LubricationSettings lube_;
  bool lube_keyword_ = false;         // the keyword was given (even as none): define the variables
  std::string breakdown_text_ = "0";  // the keyword breakdown's word, for lubricant_breakdown
  std::unique_ptr<LubricatedBearing> lubricated_;
  LubricatedResult lube_result_;
  std::unique_ptr<LubricatedVtk> lube_vtk_;  // with a lubricant: the contacts' VTK file
  void define_lubricant_variables();
  void lube_impedance();

  bigint evaluated_step_ = -1;
  bigint minima_step_ = -1;     // step whose lube_result_ holds the reduced minima
  bigint impedance_step_ = -1;  // step whose lube_result_ holds the impedance (lube_impedance())
  double result_[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  bool warned_no_path_ = false;
  bool warned_short_ = false;  // the electrodes touch (said once)
  bool had_path_ = false;           // a conducting path existed at some evaluation
  long long lost_evaluations_ = 0;  // evaluations without a path after one existed
  int nmax_ = 0;
  bigint potentials_step_ = -1;  // step whose per-atom potentials are filled
};

}  // namespace LAMMPS_NS

#endif
#endif
