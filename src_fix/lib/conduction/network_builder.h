// SPDX-License-Identifier: GPL-2.0-or-later
// The general evaluation of the conduction model: the contact network of any scene (races,
// particle-particle contacts, electrode groups) as a ConductionNetwork, plain C++ (no
// LIGGGHTS types). The records are what compute network/resistance gathers over MPI, each
// with its pack/unpack beside it.
#ifndef OHMDEM_NETWORK_BUILDER_H
#define OHMDEM_NETWORK_BUILDER_H

#include <cstdint>
#include <functional>
#include <vector>

#include "common/ordered_reduce.h"
#include "conduction/conduction_model.h"
#include "network/conduction_network.h"
#include "network/network_export.h"

namespace ohmdem {

// Which electrode group a particle belongs to.
enum class Membership { None = 0, High = 1, Low = 2 };

// A conducting particle as gathered from all processes.
struct ParticleRecord {
  std::int64_t tag = 0;
  double centre[3] = {0, 0, 0};  // m
  double radius = 0;             // m
  int type = 0;                  // atom type
  Membership member = Membership::None;

  using Packed = TaggedValues<6>;
  Packed pack() const
  {
    return {tag,
            {centre[0], centre[1], centre[2], radius, static_cast<double>(type),
             static_cast<double>(member)}};
  }
  static ParticleRecord unpack(const Packed &p)
  {
    return {p.tag,
            {p.v[0], p.v[1], p.v[2]},
            p.v[3],
            static_cast<int>(p.v[4]),
            static_cast<Membership>(static_cast<int>(p.v[5]))};
  }
};

// A contact of particle `tag` with particle `other` (race < 0) or with race `race` (other 0).
struct ContactRecord {
  std::int64_t tag = 0;
  std::int64_t other = 0;
  int race = -1;
  double fn = 0;                // N
  double point[3] = {0, 0, 0};  // m
  double a = 0, b = 0;          // semi-axes of the contact ellipse (m)

  using Packed = TaggedValues<8>;
  Packed pack() const
  {
    return {tag,
            {static_cast<double>(other), static_cast<double>(race), fn, point[0], point[1],
             point[2], a, b}};
  }
  static ContactRecord unpack(const Packed &p)
  {
    return {p.tag,  static_cast<std::int64_t>(p.v[0]), static_cast<int>(p.v[1]),
            p.v[2], {p.v[3], p.v[4], p.v[5]},          p.v[6],
            p.v[7]};
  }
};

// Node keys of the electrodes: below 2^32 (conduction_network.h); tags stay below these.
NodeKey race_node(int race);
NodeKey member_node(Membership m);  // High or Low

struct NetworkScene {
  const std::vector<ParticleRecord> *particles;  // sorted by tag
  const std::vector<ContactRecord> *contacts;
  const std::vector<double> *gamma_type;  // conductivity of each atom type (S/m), 1-based
  const std::vector<double> *gamma_race;  // conductivity of each race (S/m)
  bool draw = false;                      // fill NetworkBuild::drawn (VTK)
  // A rank's share of a distributed network (sorted tags; nullptr: the whole network): the
  // bulk law of these particles only, and the constriction (and count) of a contact only if
  // its first particle (ContactRecord::tag) is one of these, so each edge is built once.
  const std::vector<std::int64_t> *owned_tags = nullptr;
};

struct NetworkBuild {
  struct Spot {
    std::int64_t tag;  // the particle whose side of a contact this is
    ContactSpot spot;
    int contact = -1;  // index of its contact in NetworkScene::contacts
  };
  std::vector<Spot> spots;  // sorted by tag
  std::vector<VtkEdge> drawn;
  int conducting_contacts = 0;
  // Conducting contacts that join two electrodes directly (the electrodes touch) where the
  // model gives a contact spot no resistance (no constriction slot): a short circuit, which
  // the network cannot hold as an edge. The first one's particle tags (0: a race).
  int electrode_shorts = 0;
  std::int64_t short_tags[2] = {0, 0};
};

// Clears `net` and adds the model's conductances: a constriction per conducting contact,
// the bulk law inside every conducting particle that is not part of an electrode. `out` is
// cleared and filled (its memory is reused from call to call).
void build_network(const ConductionModel &model, const NetworkScene &scene, ConductionNetwork &net,
                   NetworkBuild &out);
// The same conductances given to `sink` (a, b, g) one by one, in the same order (the
// distributed path keeps its share as a plain list of edges).
using ConductanceSink = std::function<void(NodeKey, NodeKey, double)>;
void build_network(const ConductionModel &model, const NetworkScene &scene,
                   const ConductanceSink &sink, NetworkBuild &out);

}  // namespace ohmdem

#endif
