// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: the SPICE netlist and VTK exports of the gathered network
// (keywords netlist, vtk and every), checked on every process at the start of a run, written
// by process 0. A `*` in a file name stands for the step; a VTK series gets a ParaView index
// (.pvd) and, per written step, the particles and (when it moved) the bearing geometry.
// Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_NETWORK_EXPORTS_H
#define OHMDEM_STYLE_NETWORK_EXPORTS_H

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "lmptype.h"
#include "pointers.h"
#include "writers/vtk_series.h"

namespace LAMMPS_NS {

class ContactSet;
class GatheredNetworkPath;
// Writes another netlist in place of the network's (the lubricated bearing's AC netlist).
using AcNetlistFn = std::function<void(std::ostream &)>;
// Writes one more VTK file of the step (the lubricated contacts, lubricated_vtk.h).
using VtkPartFn = std::function<void(std::ostream &)>;

class NetworkExports : protected Pointers {
 public:
  // File patterns ("" for none) and the step period (0: every evaluation).
  NetworkExports(LAMMPS *lmp, std::string netlist, std::string vtk, bigint every);
  ~NetworkExports();
  bool any() const { return !netlist_.empty() || !vtk_.empty(); }
  bool draws() const { return !vtk_.empty(); }
  // An export is written at this step: the compute evaluates the gathered network then.
  bool due(bigint step) const { return any() && (every_ == 0 || step % every_ == 0); }
  // At the start of a run, on every process: stops the run if a file cannot be written.
  void check_files();
  // Process 0, after the gathered network's evaluation on step `step` (nothing unless due);
  // `ac`, when set, writes the netlist file instead of the network's DC netlist; `lubricated`,
  // when set, BASE_lubricated[.STEP].vtk beside the network (part 3 of the .pvd).
  void write(const GatheredNetworkPath &network, const ContactSet &contacts, double current,
             const AcNetlistFn &ac = nullptr, const VtkPartFn &lubricated = nullptr);

 private:
  std::string write_particles(const GatheredNetworkPath &network, const std::string &path);
  // "" without a race; rewritten only when it moved.
  std::string write_bearing_geometry(const GatheredNetworkPath &network,
                                     const ContactSet &contacts);

  std::string netlist_, vtk_;  // a `*` stands for the step (vtk_series.h)
  bigint every_ = 0;
  std::unique_ptr<ohmdem::PvdIndex> pvd_;  // the .pvd of a VTK series
  std::vector<double> geometry_drawn_;     // what the last bearing geometry file shows
  std::string geometry_file_;
};

}  // namespace LAMMPS_NS

#endif
