// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance, the gathered network; see resistance_path_gathered.h.
#include "ELECTRIC/resistance_path_gathered.h"

#include <algorithm>
#include <cstdint>

#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "common/ordered_reduce.h"

using namespace LAMMPS_NS;

GatheredNetworkPath::GatheredNetworkPath(LAMMPS *lmp, const ResistanceContext &context)
    : Pointers(lmp), context_(context), network_(std::make_unique<ohmdem::ConductionNetwork>())
{
}

GatheredNetworkPath::~GatheredNetworkPath() = default;

void GatheredNetworkPath::set_options(const ohmdem::SolverOptions &options, bool draw)
{
  network_->set_options(options);
  draw_ = draw;
}

ohmdem::SolverOptions GatheredNetworkPath::options() const
{
  return network_->options();
}

// The particles and contacts of all processes, in tag order.
void GatheredNetworkPath::gather_scene()
{
  context_.contacts->collect(local_contacts_);
  std::vector<ohmdem::ParticleRecord::Packed> my_particles;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & context_.groupbit)
      my_particles.push_back(context_.particle(*atom, i).pack());
  std::vector<ohmdem::ContactRecord::Packed> my_contacts;
  for (const auto &c : local_contacts_) my_contacts.push_back(c.pack());
  const auto all_particles = ohmdem::gather_by_tag<6>(my_particles, world);
  particles_.resize(all_particles.size());
  for (std::size_t k = 0; k < all_particles.size(); ++k)
    particles_[k] = ohmdem::ParticleRecord::unpack(all_particles[k]);
  const auto all_contacts = ohmdem::gather_by_tag<8>(my_contacts, world);
  contacts_.resize(all_contacts.size());
  for (std::size_t k = 0; k < all_contacts.size(); ++k)
    contacts_[k] = ohmdem::ContactRecord::unpack(all_contacts[k]);
}

bool GatheredNetworkPath::evaluate(double *phi, PathResult &result)
{
  gather_scene();
  context_.gamma_race(gamma_race_);

  // The model's conductances: constrictions across contacts, the bulk law inside particles.
  ohmdem::ConductionNetwork &net = *network_;
  const ohmdem::NetworkScene scene{&particles_, &contacts_, &context_.gamma_type, &gamma_race_,
                                   draw_};
  ohmdem::build_network(context_.model, scene, net, built_);

  // Solve: current into `high`, `low` at 0 V.
  net.set_electrodes(context_.high.node(ohmdem::Membership::High),
                     context_.low.node(ohmdem::Membership::Low));
  const ohmdem::NetworkSolution sol = net.solve(context_.current);
  result = PathResult{sol.resistance, built_.conducting_contacts, sol.floating_nodes_dropped,
                      sol.iterations, sol.relative_residual};
  result.shorts = built_.electrode_shorts;
  result.short_tags[0] = built_.short_tags[0];
  result.short_tags[1] = built_.short_tags[1];

  // Per-atom potential: mean over the particle's contact nodes (0 without a contact).
  const auto &spots = built_.spots;
  for (int i = 0; i < atom->nlocal; ++i) {
    phi[i] = 0.0;
    if (!(atom->mask[i] & context_.groupbit)) continue;
    const std::int64_t tag = atom->tag[i];
    auto lo = std::lower_bound(
        spots.begin(), spots.end(), tag,
        [](const ohmdem::NetworkBuild::Spot &x, std::int64_t t) { return x.tag < t; });
    double sum = 0.0;
    int n = 0;
    for (; lo != spots.end() && lo->tag == tag; ++lo, ++n) sum += net.potential(lo->spot.node);
    phi[i] = n ? sum / n : 0.0;
  }
  return true;
}

// Rows of the whole (gathered) network, kept for the atoms owned here.
void GatheredNetworkPath::contact_flows(std::vector<ohmdem::ContactFlow> &rows)
{
  const ohmdem::NetworkScene scene{&particles_, &contacts_, &context_.gamma_type, &gamma_race_,
                                   false};
  ohmdem::network_contact_flows(context_.model, scene, built_, *network_, all_flows_);
  std::vector<std::int64_t> mine;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & context_.groupbit) mine.push_back(static_cast<std::int64_t>(atom->tag[i]));
  std::sort(mine.begin(), mine.end());
  for (const auto &row : all_flows_)
    if (std::binary_search(mine.begin(), mine.end(), row.atom)) rows.push_back(row);
}
