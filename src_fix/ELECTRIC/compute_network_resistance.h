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
#include <vector>

#include "common/ordered_reduce.h"
#include "compute.h"
#include "conduction/conduction_model.h"
#include "conduction/contact_flows.h"
#include "conduction/network_builder.h"
#include "writers/vtk_series.h"

namespace ohmdem {
class ConductionNetwork;
}

namespace LAMMPS_NS {

class ContactSet;
class FixBearingRace;
class NetworkResistanceDistributed;

class ComputeNetworkResistance : public Compute {
 public:
  ComputeNetworkResistance(class LAMMPS *, int &iarg, int, char **);
  ~ComputeNetworkResistance() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  void compute_local() override;  // compute_network_resistance_local.cpp
  double memory_usage() override;

 private:
  enum class ElectrodeKind { Race, Group };
  struct Electrode {
    ElectrodeKind kind = ElectrodeKind::Race;
    std::string name;
    int index = -1;  // race: index in the contact set's races; group: group bit
  };

  void parse(int narg, char **arg);
  void evaluate();                // builds and solves the network once per time step
  bool evaluate_between_races();  // closed form when every ball joins the two races
  void build_and_solve();         // the general network
  bool use_distributed();         // compute_network_resistance_distributed.cpp
  void solve_distributed();
  void gather_scene(std::vector<ohmdem::ParticleRecord> &particles,
                    std::vector<ohmdem::ContactRecord> &contacts);
  void write_exports(const std::vector<ohmdem::VtkEdge> &drawn);
  // compute_network_resistance_exports.cpp: the VTK companions of the network file.
  std::string write_particles(const std::string &path);
  std::string write_bearing_geometry();  // "" without a race; rewritten only when it moved
  void report(double resistance, int contacts, int dropped, int iterations, double residual);
  void check_export_files();
  // The local array (compute_network_resistance_local.cpp): per-contact rows of this step.
  void closed_form_flows(std::vector<ohmdem::ContactFlow> &rows);
  void network_flows(std::vector<ohmdem::ContactFlow> &rows);
  void masked_flows(std::vector<ohmdem::ContactFlow> &rows);
  int race_electrode(int race) const;  // +1 high, -1 low, 0 neither

  double current_ = 0;
  Electrode high_, low_;
  ohmdem::ConductionModel model_;  // from the keyword `model` (conduction_model.h's table)
  int solver_ = 0;                 // ohmdem::SolverKind
  bool multigrid_ = false;         // solver amg: CG preconditioned by algebraic multigrid
  bool distributed_solver_ = false;  // solver distributed
  std::unique_ptr<NetworkResistanceDistributed> distributed_;
  bool area_exact_ = false;
  int pair_mode_ = -1;         // -1 auto (use the granular pair style if there is one), 0 no, 1 yes
  std::string netlist_, vtk_;  // a `*` stands for the step (vtk_series.h)
  bigint every_ = 0;           // exports on steps that are multiples of every_ (0: each evaluation)
  std::unique_ptr<ohmdem::PvdIndex> pvd_;  // the .pvd of a VTK series
  std::vector<double> geometry_drawn_;     // what the last bearing geometry file shows
  std::string geometry_file_;
  bool closed_form_ = true;  // keyword closedform: use the two-race closed form when it applies

  std::unique_ptr<ContactSet> contacts_;
  std::unique_ptr<ohmdem::ConductionNetwork> network_;
  class FixPropertyGlobal *conductivity_ = nullptr;
  bigint evaluated_step_ = -1;
  double result_[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  bool warned_no_path_ = false;
  bool had_path_ = false;           // a conducting path existed at some evaluation
  long long lost_evaluations_ = 0;  // evaluations without a path after one existed
  // closed form, per local ball: conductance, 1 if it joins the races, 1 if a dead end
  std::vector<ohmdem::TaggedValues<3> > balls_;
  ohmdem::OrderedGather<3> balls_gather_;
  // Closed form: the model between the two electrode races, set at the first evaluation of
  // a run (the races' geometry is known then).
  bool geometry_ready_ = false;
  ohmdem::BallBetweenRaces between_races_;
  std::vector<const FixBearingRace *> other_races_;  // neither electrode: any contact -> network
  std::vector<double> gamma_type_;  // conductivity of each atom type (S/m), 1-based
  // General network: the scene and the build, members so that their memory is reused.
  std::vector<ohmdem::ParticleRecord> particles_;
  std::vector<ohmdem::ContactRecord> contact_records_;
  std::vector<double> gamma_race_;
  ohmdem::NetworkBuild built_;
  int nmax_ = 0;
  bool closed_form_used_ = false;  // the last evaluation took the closed form
  bool distributed_used_ = false;  // the last general solve was distributed (no local rows)
  bigint potentials_step_ = -1;    // distributed: step whose per-atom potentials are filled
  // The local array: this process's rows (contacts whose atom it owns), kept for reuse.
  std::vector<ohmdem::ContactFlow> flows_, all_flows_;
  int local_capacity_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
