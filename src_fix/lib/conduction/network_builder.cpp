// SPDX-License-Identifier: GPL-2.0-or-later
// The general network of the conduction model; see network_builder.h.
#include "conduction/network_builder.h"

#include <algorithm>
#include <cmath>

namespace ohmdem {

namespace {
constexpr std::uint32_t kRaceId0 = 0xFFFFFF00u;  // race k: kRaceId0 + k
constexpr std::uint32_t kGroupHighId = 0xFFFFFFF0u;
constexpr std::uint32_t kGroupLowId = 0xFFFFFFF1u;

NodeKey particle_node(std::int64_t tag)
{
  return NodeKey(static_cast<std::uint32_t>(tag)) << 32;
}

class Builder {
 public:
  Builder(const ConductionModel &model, const NetworkScene &scene, const ConductanceSink &sink,
          NetworkBuild &out)
      : model_(model), scene_(scene), sink_(sink), out_(out)
  {
  }
  void run();

 private:
  const ParticleRecord *find(std::int64_t tag) const;
  bool owned(std::int64_t tag) const
  {
    const auto *t = scene_.owned_tags;
    return !t || std::binary_search(t->begin(), t->end(), tag);
  }
  NodeKey side_node(const ParticleRecord &p, std::uint32_t other, NodeKey shared) const;
  void add_contact(const ContactRecord &c);
  void add_bulk();

  const ConductionModel &model_;
  const NetworkScene &scene_;
  const ConductanceSink &sink_;
  NetworkBuild &out_;
  std::vector<ContactSpot> mine_;  // add_bulk: the spots of one particle
};

const ParticleRecord *Builder::find(std::int64_t tag) const
{
  const auto &ps = *scene_.particles;
  auto it = std::lower_bound(ps.begin(), ps.end(), tag,
                             [](const ParticleRecord &p, std::int64_t t) { return p.tag < t; });
  return it != ps.end() && it->tag == tag ? &*it : nullptr;
}

// Node of particle p's side of a contact with `other` (a tag, or kRaceId0 + race): the
// electrode's node for an electrode particle; without a bulk law the particle is one node;
// with both slots each side of a contact is a node of its own (the constriction between).
NodeKey Builder::side_node(const ParticleRecord &p, std::uint32_t other, NodeKey shared) const
{
  if (p.member != Membership::None) return member_node(p.member);
  if (!model_.has_bulk()) return particle_node(p.tag);
  if (model_.has_constriction()) return contact_side_key(static_cast<std::uint32_t>(p.tag), other);
  return shared;
}

void Builder::add_contact(const ContactRecord &c)
{
  const ParticleRecord *p = find(c.tag);
  if (!p) return;
  const double area = kPi * c.a * c.b;
  const double gp = (*scene_.gamma_type)[p->type];
  double go = 0.0;
  NodeKey shared, other_side;
  std::uint32_t other_id;
  const ParticleRecord *q = nullptr;
  if (c.race >= 0) {
    other_id = kRaceId0 + static_cast<std::uint32_t>(c.race);
    shared = other_side = race_node(c.race);
    go = (*scene_.gamma_race)[c.race];
  } else {
    q = find(c.other);
    if (!q) return;  // the other particle is outside the group
    other_id = static_cast<std::uint32_t>(q->tag);
    shared = p->member != Membership::None ? member_node(p->member)
             : q->member != Membership::None
                 ? member_node(q->member)
                 : contact_key(static_cast<std::uint32_t>(p->tag), other_id);
    go = (*scene_.gamma_type)[q->type];
    other_side = side_node(*q, static_cast<std::uint32_t>(p->tag), shared);
  }
  if (!(gp > 0.0) || !(go > 0.0)) return;  // an insulator on either side: no current
  const bool built_here = owned(p->tag);
  if (built_here) ++out_.conducting_contacts;
  const NodeKey mine = side_node(*p, other_id, shared);
  const double *pt = c.point;
  const int index = static_cast<int>(&c - scene_.contacts->data());
  out_.spots.push_back({p->tag, {mine, {pt[0], pt[1], pt[2]}, area}, index});
  if (q) out_.spots.push_back({q->tag, {other_side, {pt[0], pt[1], pt[2]}, area}, index});
  // electrode keys lie below 2^32 (conduction_network.h)
  const auto electrode = [](NodeKey k) { return k <= electrode_key(0xffffffffu); };
  if (!model_.has_constriction() && built_here && mine != other_side && electrode(mine) &&
      electrode(other_side) && out_.electrode_shorts++ == 0) {
    out_.short_tags[0] = p->tag;
    out_.short_tags[1] = q ? q->tag : 0;
  }
  if (!model_.has_constriction() || !built_here) return;
  // The constriction of the spot, in series between the two bodies.
  const double rc = model_.constriction_resistance(gp, go, c.a, c.b);
  if (!(std::isfinite(rc) && rc > 0.0)) return;
  sink_(mine, other_side, 1.0 / rc);
  if (scene_.draw)
    out_.drawn.push_back({mine,
                          other_side,
                          1.0 / rc,
                          {pt[0], pt[1], pt[2]},
                          {pt[0], pt[1], pt[2]},
                          {area, area, 1.0}});
}

// The bulk law inside every conducting particle that is not part of an electrode.
void Builder::add_bulk()
{
  const auto &spots = out_.spots;
  std::vector<ContactSpot> &mine = mine_;
  const bool draw = scene_.draw;
  const EdgeVisitor visit = [&](const ContactSpot &x, const ContactSpot &y, double g) {
    sink_(x.node, y.node, g);
    if (draw)
      out_.drawn.push_back({x.node,
                            y.node,
                            g,
                            {x.point[0], x.point[1], x.point[2]},
                            {y.point[0], y.point[1], y.point[2]},
                            {x.area, y.area, 0.0}});
  };
  for (std::size_t s = 0; s < spots.size();) {
    std::size_t e = s;
    while (e < spots.size() && spots[e].tag == spots[s].tag) ++e;
    const ParticleRecord *p = find(spots[s].tag);
    if (p && p->member == Membership::None && owned(p->tag)) {
      mine.clear();
      for (std::size_t k = s; k < e; ++k) mine.push_back(spots[k].spot);
      const ConductingParticle cp{{p->centre[0], p->centre[1], p->centre[2]},
                                  p->radius,
                                  sphere_volume(p->radius),
                                  (*scene_.gamma_type)[p->type]};
      for_each_particle_conductance(cp, mine.data(), mine.size(), visit);
    }
    s = e;
  }
}

void Builder::run()
{
  out_.spots.clear();
  out_.drawn.clear();
  out_.conducting_contacts = 0;
  out_.electrode_shorts = 0;
  out_.short_tags[0] = out_.short_tags[1] = 0;
  for (const ContactRecord &c : *scene_.contacts) add_contact(c);
  std::stable_sort(
      out_.spots.begin(), out_.spots.end(),
      [](const NetworkBuild::Spot &x, const NetworkBuild::Spot &y) { return x.tag < y.tag; });
  if (model_.has_bulk()) add_bulk();
}
}  // namespace

NodeKey race_node(int race)
{
  return electrode_key(kRaceId0 + static_cast<std::uint32_t>(race));
}

NodeKey member_node(Membership m)
{
  return electrode_key(m == Membership::High ? kGroupHighId : kGroupLowId);
}

void build_network(const ConductionModel &model, const NetworkScene &scene, ConductionNetwork &net,
                   NetworkBuild &out)
{
  net.clear();
  build_network(
      model, scene, [&net](NodeKey a, NodeKey b, double g) { net.add_conductance(a, b, g); }, out);
}

void build_network(const ConductionModel &model, const NetworkScene &scene,
                   const ConductanceSink &sink, NetworkBuild &out)
{
  Builder(model, scene, sink, out).run();
}

}  // namespace ohmdem
