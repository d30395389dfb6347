// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance, the distributed path; see
   resistance_path_distributed.h.
------------------------------------------------------------------------- */

#include "ELECTRIC/resistance_path_distributed.h"

#include <mpi.h>

#include <algorithm>
#include <string>
#include <tuple>

#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "network/key_directory.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// A contact between processes, sent to the owner of its second particle with the first one.
struct Routed {
  ohmdem::ContactRecord::Packed contact;
  ohmdem::ParticleRecord::Packed first;
};

// The particle owning a node (NodeKey scheme of network_builder.cpp: the tag is the upper
// 32 bits, that of the smaller tag for a node shared by two particles); 0 for an electrode
// or a race.
std::int64_t particle_of(ohmdem::NodeKey k)
{
  return static_cast<std::int64_t>(k >> 32);
}

}  // namespace

DistributedNetworkPath::DistributedNetworkPath(LAMMPS *lmp, const ResistanceContext &context)
    : Pointers(lmp),
      context_(context),
      solver_(std::make_unique<ohmdem::DistributedNetworkSolver>(world))
{
}

DistributedNetworkPath::~DistributedNetworkPath() = default;

// Every contact of this process's particles, and the particles at their other ends: a
// contact held here whose partner is owned elsewhere also goes to the partner's owner (found
// through a directory of tags), so both owners can build the bulk law of their particle.
void DistributedNetworkPath::route()
{
  std::vector<ohmdem::ContactRecord> &local = collected_;
  context_.contacts->collect(local);
  owned_tags_.clear();
  particles_.clear();
  // Each local or ghost particle recorded once (a partner has several contacts here).
  recorded_.assign(static_cast<std::size_t>(atom->nlocal) + atom->nghost, 0);
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & context_.groupbit)) continue;
    owned_tags_.push_back(static_cast<std::int64_t>(atom->tag[i]));
    particles_.push_back(context_.particle(*atom, i));
    recorded_[i] = 1;
  }
  std::sort(owned_tags_.begin(), owned_tags_.end());

  ohmdem::KeyDirectory owners(world);
  {
    std::vector<ohmdem::KeyDirectory::Entry> mine;
    for (std::int64_t t : owned_tags_) mine.push_back({static_cast<std::uint64_t>(t), comm->me});
    owners.publish(mine);
  }
  std::vector<ohmdem::KeyDirectory::Key> partners;
  for (const auto &c : local)
    if (c.race < 0) partners.push_back(static_cast<std::uint64_t>(c.other));
  const std::vector<std::int64_t> owner = owners.lookup(partners);

  contacts_.clear();
  std::vector<std::vector<Routed>> out(comm->nprocs);
  std::size_t q = 0;
  for (const ohmdem::ContactRecord &rec : local) {
    contacts_.push_back(rec);
    if (rec.race >= 0) continue;
    const std::int64_t o = owner[q++];
    const int j = atom->map(static_cast<tagint>(rec.other));  // the partner, owned or a ghost
    if (j >= 0 && !recorded_[j]) {
      recorded_[j] = 1;
      particles_.push_back(context_.particle(*atom, j));
    }
    if (o != comm->me && o != ohmdem::KeyDirectory::kMissing) {
      const int i = atom->map(static_cast<tagint>(rec.tag));
      out[o].push_back({rec.pack(), context_.particle(*atom, i).pack()});
    }
  }
  for (const Routed &r : ohmdem::exchange_blocks(out, world)) {
    contacts_.push_back(ohmdem::ContactRecord::unpack(r.contact));
    particles_.push_back(ohmdem::ParticleRecord::unpack(r.first));
  }
  // Sorted: the build's order, hence the numbers, do not depend on arrival order.
  std::sort(particles_.begin(), particles_.end(),
            [](const ohmdem::ParticleRecord &a, const ohmdem::ParticleRecord &b) {
              return a.tag < b.tag;
            });
  particles_.erase(std::unique(particles_.begin(), particles_.end(),
                               [](const ohmdem::ParticleRecord &a,
                                  const ohmdem::ParticleRecord &b) { return a.tag == b.tag; }),
                   particles_.end());
  std::sort(contacts_.begin(), contacts_.end(),
            [](const ohmdem::ContactRecord &a, const ohmdem::ContactRecord &b) {
              return std::tie(a.tag, a.race, a.other) < std::tie(b.tag, b.race, b.other);
            });
}

bool DistributedNetworkPath::evaluate(double * /*phi*/, PathResult &result)
{
  route();
  context_.gamma_race(gamma_race_);
  const ohmdem::NodeKey high = context_.high.node(ohmdem::Membership::High);
  const ohmdem::NodeKey low = context_.low.node(ohmdem::Membership::Low);
  const ohmdem::NetworkScene scene{&particles_,  &contacts_, &context_.gamma_type,
                                   &gamma_race_, false,      &owned_tags_};
  // This process's share of the conductances, and the nodes it owns: the contact nodes of
  // its particles (a node shared by two particles: the one with the smaller tag), and on
  // rank 0 the races that are not electrodes but conduct somewhere.
  share_.clear();
  const int nraces = static_cast<int>(gamma_race_.size());
  std::vector<int> race_used(nraces, 0);
  auto note_race = [&](ohmdem::NodeKey k) {
    for (int r = 0; r < nraces; ++r)
      if (k == ohmdem::race_node(r) && k != high && k != low) race_used[r] = 1;
  };
  ohmdem::build_network(
      context_.model, scene,
      [&](ohmdem::NodeKey a, ohmdem::NodeKey b, double g) {
        share_.push_back({a, b, g});
        if (particle_of(a) == 0) note_race(a);
        if (particle_of(b) == 0) note_race(b);
      },
      built_);
  if (nraces) MPI_Allreduce(MPI_IN_PLACE, race_used.data(), nraces, MPI_INT, MPI_MAX, world);
  owned_nodes_.clear();
  for (const auto &s : built_.spots)
    if (particle_of(s.spot.node) == s.tag &&
        std::binary_search(owned_tags_.begin(), owned_tags_.end(), s.tag))
      owned_nodes_.push_back(s.spot.node);
  if (comm->me == 0)
    for (int r = 0; r < nraces; ++r)
      if (race_used[r]) owned_nodes_.push_back(ohmdem::race_node(r));

  const ohmdem::DistributedSolution s =
      solver_->solve(owned_nodes_, share_, high, low, context_.current);
  long long n = built_.conducting_contacts, contacts = 0;
  MPI_Allreduce(&n, &contacts, 1, MPI_LONG_LONG, MPI_SUM, world);
  if (!s.converged && comm->me == 0)
    error->warning(FLERR,
                   ("compute network/resistance: the distributed CG stopped at step " +
                    std::to_string(update->ntimestep) + " after " + std::to_string(s.iterations) +
                    " iterations, relative residual " + std::to_string(s.relative_residual))
                       .c_str());
  result = PathResult{s.resistance, static_cast<int>(contacts), static_cast<int>(s.floating_nodes),
                      s.iterations, s.relative_residual};
  long long shorts[3] = {built_.electrode_shorts, built_.short_tags[0], built_.short_tags[1]};
  long long all[3] = {0, 0, 0};
  MPI_Allreduce(&shorts[0], &all[0], 1, MPI_LONG_LONG, MPI_SUM, world);
  MPI_Allreduce(&shorts[1], &all[1], 2, MPI_LONG_LONG, MPI_MAX, world);
  result.shorts = static_cast<int>(all[0]);
  result.short_tags[0] = all[1];
  result.short_tags[1] = all[2];
  return true;
}

void DistributedNetworkPath::potentials(double *phi)
{
  // The mean over the particle's contact nodes (0 without a contact).
  std::vector<ohmdem::NodeKey> keys;
  for (const auto &s : built_.spots)
    if (std::binary_search(owned_tags_.begin(), owned_tags_.end(), s.tag))
      keys.push_back(s.spot.node);
  const std::vector<double> v = solver_->potentials(keys);
  std::vector<std::pair<std::int64_t, double>> by_tag;
  std::size_t k = 0;
  for (const auto &s : built_.spots)
    if (std::binary_search(owned_tags_.begin(), owned_tags_.end(), s.tag))
      by_tag.push_back({s.tag, v[k++]});
  for (int i = 0; i < atom->nlocal; ++i) {
    phi[i] = 0.0;
    if (!(atom->mask[i] & context_.groupbit)) continue;
    const std::int64_t tag = atom->tag[i];
    auto lo = std::lower_bound(
        by_tag.begin(), by_tag.end(), tag,
        [](const std::pair<std::int64_t, double> &x, std::int64_t t) { return x.first < t; });
    double sum = 0.0;
    int m = 0;
    for (; lo != by_tag.end() && lo->first == tag; ++lo, ++m) sum += lo->second;
    phi[i] = m ? sum / m : 0.0;
  }
}

void DistributedNetworkPath::contact_flows(std::vector<ohmdem::ContactFlow> & /*rows*/)
{
  error->all(FLERR,
             "compute network/resistance: the per-contact local array needs the gathered "
             "network solve, not solver distributed (solver auto goes distributed from 20000 "
             "particles on more than one process): give solver direct, cg or amg");
}

double DistributedNetworkPath::memory_usage() const
{
  return static_cast<double>(solver_->memory_bytes()) +
         static_cast<double>(particles_.capacity() * sizeof(ohmdem::ParticleRecord) +
                             contacts_.capacity() * sizeof(ohmdem::ContactRecord) +
                             built_.spots.capacity() * sizeof(ohmdem::NetworkBuild::Spot) +
                             share_.capacity() * sizeof(ohmdem::DistributedEdge) +
                             owned_nodes_.capacity() * sizeof(ohmdem::NodeKey));
}
