// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance: the SPICE netlist and VTK exports; see network_exports.h.
#include "ELECTRIC/network_exports.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "BEARING/fix_bearing_cage.h"
#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/resistance_path_gathered.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "network/conduction_network.h"
#include "network/network_export.h"
#include "update.h"
#include "writers/scene_vtk.h"
#include "writers/vtk_series.h"

using namespace LAMMPS_NS;

NetworkExports::NetworkExports(LAMMPS *lmp, std::string netlist, std::string vtk, bigint every)
    : Pointers(lmp), netlist_(std::move(netlist)), vtk_(std::move(vtk)), every_(every)
{
}

NetworkExports::~NetworkExports() = default;

// The netlist and VTK files are written by process 0 during the run; a path that cannot be
// written stops the run here, on every process alike, with the message in the log (an error
// raised on one process only aborts MPI before the log is written). A series is checked with
// the file of the current step, removed again if it was not there.
void NetworkExports::check_files()
{
  for (const auto &[kw, pattern] :
       {std::pair<const char *, const std::string &>{"netlist", netlist_}, {"vtk", vtk_}}) {
    if (pattern.empty()) continue;
    const std::string path = ohmdem::expand_step(pattern, update->ntimestep);
    int ok = 1;
    if (comm->me == 0) {
      const bool existed = static_cast<bool>(std::ifstream(path));
      ok = std::ofstream(path, std::ios::app) ? 1 : 0;
      if (ok && !existed) std::remove(path.c_str());
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, world);
    if (!ok) {
      const std::string msg = std::string("compute network/resistance: keyword '") + kw +
                              "': cannot open '" + path + "' for writing";
      error->all(FLERR, msg.c_str());
    }
  }
  if (!vtk_.empty() && ohmdem::has_step_wildcard(vtk_) && !pvd_)
    pvd_ = std::make_unique<ohmdem::PvdIndex>(ohmdem::pvd_path(vtk_));
}

// The particles of the network at this step (all of them, gathered), with the potential of
// each: the mean of its contact-node potentials, as the per-atom output.
std::string NetworkExports::write_particles(const GatheredNetworkPath &network,
                                            const std::string &path)
{
  const std::vector<ohmdem::ParticleRecord> &particles = network.particles();
  std::vector<ohmdem::ParticlePoint> points;
  points.reserve(particles.size());
  const auto &spots = network.built().spots;
  auto s = spots.begin();
  for (const ohmdem::ParticleRecord &p : particles) {
    while (s != spots.end() && s->tag < p.tag) ++s;
    double sum = 0.0;
    int n = 0;
    for (auto t = s; t != spots.end() && t->tag == p.tag; ++t, ++n)
      sum += network.network().potential(t->spot.node);
    points.push_back({p.tag, {p.centre[0], p.centre[1], p.centre[2]}, p.radius, n ? sum / n : 0.0});
  }
  std::ofstream os(path);
  if (!os)
    error->one(FLERR,
               ("compute network/resistance: keyword 'vtk': cannot open '" + path + "' for writing")
                   .c_str());
  ohmdem::write_particles_vtk(os, points);
  return path;
}

// The races and the cage of a bearing as surfaces: written at the first export and again
// only when a ring or the cage moved by more than 1e-4 of its radius (the outer ring's
// interference, a ring centre free in the plane, the floating cage).
std::string NetworkExports::write_bearing_geometry(const GatheredNetworkPath &network,
                                                   const ContactSet &contacts)
{
  const auto &races = contacts.races();
  if (races.empty()) return "";
  const std::vector<ohmdem::ParticleRecord> &particles = network.particles();
  const double z = particles.empty() ? 0.0 : particles.front().centre[2];
  std::vector<ohmdem::RingShape> rings;
  std::vector<double> state;
  for (const FixBearingRace *r : races) {
    ohmdem::RingShape s;
    r->centre(s.centre[0], s.centre[1]);
    s.z = z;
    s.radius = r->current_radius();
    s.groove = r->groove();
    s.inner = r->is_inner();
    rings.push_back(s);
    state.insert(state.end(), {s.centre[0], s.centre[1], s.radius});
  }
  const FixBearingCage *cage_fix = nullptr;
  for (int k = 0; k < modify->nfix && !cage_fix; ++k)
    cage_fix = dynamic_cast<const FixBearingCage *>(modify->fix[k]);
  ohmdem::CageShape cage;
  if (cage_fix) {
    cage_fix->centre(cage.centre[0], cage.centre[1]);
    cage.z = z;
    cage.radius = cage_fix->pitch_radius();
    double rmax = 0.0;
    for (const auto &p : particles) rmax = std::max(rmax, p.radius);
    cage.height = rmax;
    state.insert(state.end(), {cage.centre[0], cage.centre[1], cage.radius});
  }
  bool moved = geometry_drawn_.size() != state.size();
  for (std::size_t k = 0; k < state.size() && !moved; k += 3) {
    const double tol = 1e-4 * state[k + 2];
    moved =
        std::hypot(state[k] - geometry_drawn_[k], state[k + 1] - geometry_drawn_[k + 1]) > tol ||
        std::abs(state[k + 2] - geometry_drawn_[k + 2]) > tol;
  }
  if (!moved) return geometry_file_;
  geometry_file_ = ohmdem::companion_path(vtk_, "bearing", update->ntimestep);
  std::ofstream os(geometry_file_);
  if (!os)
    error->one(FLERR, ("compute network/resistance: keyword 'vtk': cannot open '" + geometry_file_ +
                       "' for writing")
                          .c_str());
  ohmdem::write_bearing_vtk(os, rings, cage_fix ? &cage : nullptr);
  geometry_drawn_ = state;
  return geometry_file_;
}

// The network as a SPICE netlist and as a VTK file, when asked for (rank 0 only), on the
// steps of `every`.
void NetworkExports::write(const GatheredNetworkPath &network, const ContactSet &contacts,
                           double current, const AcNetlistFn &ac, const VtkPartFn &lubricated)
{
  const bigint step = update->ntimestep;
  if (every_ > 0 && step % every_ != 0) return;
  const ohmdem::ConductionNetwork &net = network.network();
  if (!netlist_.empty()) {
    const std::string path = ohmdem::expand_step(netlist_, step);
    std::ofstream os(path);
    if (!os) {
      const std::string msg =
          "compute network/resistance: keyword 'netlist': cannot open '" + path + "' for writing";
      error->one(FLERR, msg.c_str());
    }
    if (ac)
      ac(os);
    else
      ohmdem::write_spice_netlist(os, net, current);
  }
  if (!vtk_.empty()) {
    const std::string path = ohmdem::expand_step(vtk_, step);
    std::ofstream os(path);
    if (!os) {
      const std::string msg =
          "compute network/resistance: keyword 'vtk': cannot open '" + path + "' for writing";
      error->one(FLERR, msg.c_str());
    }
    // Cells: eq. 1 conductances inside particles (drawn between the two contact points) and
    // Holm constrictions (a point cell at the contact); cell data as in network_export.h.
    ohmdem::VtkOptions opt;
    opt.edge_scalar_names = {"area_a", "area_b", "holm"};
    ohmdem::write_vtk_network(os, net, network.built().drawn, opt);
    std::vector<std::string> files{
        path, write_particles(network, ohmdem::companion_path(vtk_, "particles", step))};
    const std::string geometry = write_bearing_geometry(network, contacts);
    if (!geometry.empty()) files.push_back(geometry);
    if (lubricated) {
      files.push_back(ohmdem::companion_path(vtk_, "lubricated", step));
      std::ofstream part(files.back());
      if (!part)
        error->one(FLERR, ("compute network/resistance: keyword 'vtk': cannot open '" +
                           files.back() + "' for writing")
                              .c_str());
      lubricated(part);
    }
    if (pvd_) {
      try {
        pvd_->add(step, update->atime + static_cast<double>(step - update->atimestep) * update->dt,
                  files);
      } catch (const std::exception &e) {
        error->one(FLERR,
                   (std::string("compute network/resistance: keyword 'vtk': ") + e.what()).c_str());
      }
    }
  }
}
