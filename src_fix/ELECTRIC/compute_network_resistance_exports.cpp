// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: the SPICE netlist and VTK exports of the network (keywords
// netlist and vtk), checked on every process at the start of a run, written by process 0.
#include <mpi.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "ELECTRIC/compute_network_resistance.h"
#include "comm.h"
#include "error.h"
#include "network/conduction_network.h"
#include "network/network_export.h"

using namespace LAMMPS_NS;

// The netlist and VTK files are written by process 0 during the run; a path that cannot be
// written stops the run here, on every process alike, with the message in the log (an error
// raised on one process only aborts MPI before the log is written).
void ComputeNetworkResistance::check_export_files()
{
  for (const auto &[kw, path] :
       {std::pair<const char *, const std::string &>{"netlist", netlist_}, {"vtk", vtk_}}) {
    if (path.empty()) continue;
    int ok = 1;
    if (comm->me == 0) ok = std::ofstream(path, std::ios::app) ? 1 : 0;
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok) {
      const std::string msg = std::string("compute network/resistance: keyword '") + kw +
                              "': cannot open '" + path + "' for writing";
      error->all(FLERR, msg.c_str());
    }
  }
}

// The network as a SPICE netlist and as a VTK file, when asked for (rank 0 only).
void ComputeNetworkResistance::write_exports(const std::vector<ohmdem::VtkEdge> &drawn)
{
  const ohmdem::ConductionNetwork &net = *network_;
  if (!netlist_.empty()) {
    std::ofstream os(netlist_);
    if (!os) {
      const std::string msg = "compute network/resistance: keyword 'netlist': cannot open '" +
                              netlist_ + "' for writing";
      error->one(FLERR, msg.c_str());
    }
    ohmdem::write_spice_netlist(os, net, current_);
  }
  if (!vtk_.empty()) {
    std::ofstream os(vtk_);
    if (!os) {
      const std::string msg =
          "compute network/resistance: keyword 'vtk': cannot open '" + vtk_ + "' for writing";
      error->one(FLERR, msg.c_str());
    }
    // Cells: eq. 1 conductances inside particles (drawn between the two contact points) and
    // Holm constrictions (a point cell at the contact); cell data as in network_export.h.
    ohmdem::VtkOptions opt;
    opt.edge_scalar_names = {"area_a", "area_b", "holm"};
    ohmdem::write_vtk_network(os, net, drawn, opt);
  }
}
