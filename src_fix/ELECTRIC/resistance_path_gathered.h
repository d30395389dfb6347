// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance, the gathered network: the particles and contacts of all
// processes gathered in tag order on every process (the same network, and the same numbers,
// for any process count), built with the model's conductances (electric/network_builder.h)
// and solved (network/conduction_network.h). The exports (network_exports.h) draw this
// network. Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_RESISTANCE_PATH_GATHERED_H
#define OHMDEM_STYLE_RESISTANCE_PATH_GATHERED_H

#include <memory>
#include <vector>

#include "ELECTRIC/resistance_context.h"
#include "ELECTRIC/resistance_path.h"
#include "conduction/network_builder.h"
#include "network/conduction_network.h"
#include "pointers.h"

namespace LAMMPS_NS {

class GatheredNetworkPath : public ResistancePath, protected Pointers {
 public:
  // `context` outlives the path.
  GatheredNetworkPath(LAMMPS *lmp, const ResistanceContext &context);
  ~GatheredNetworkPath() override;
  // The solver of the `solver` keyword; `draw`: keep what the VTK export draws.
  void set_options(const ohmdem::SolverOptions &options, bool draw);
  ohmdem::SolverOptions options() const;
  bool evaluate(double *phi, PathResult &result) override;
  void contact_flows(std::vector<ohmdem::ContactFlow> &rows) override;

  // The last evaluation's network, for the exports.
  const ohmdem::ConductionNetwork &network() const { return *network_; }
  const std::vector<ohmdem::ParticleRecord> &particles() const { return particles_; }
  const ohmdem::NetworkBuild &built() const { return built_; }

 private:
  void gather_scene();

  const ResistanceContext &context_;
  bool draw_ = false;
  std::unique_ptr<ohmdem::ConductionNetwork> network_;
  // The scene and the build, members so that their memory is reused.
  std::vector<ohmdem::ContactRecord> local_contacts_;
  std::vector<ohmdem::ParticleRecord> particles_;
  std::vector<ohmdem::ContactRecord> contacts_;
  std::vector<double> gamma_race_;
  ohmdem::NetworkBuild built_;
  std::vector<ohmdem::ContactFlow> all_flows_;
};

}  // namespace LAMMPS_NS

#endif
