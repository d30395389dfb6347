// SPDX-License-Identifier: GPL-2.0-or-later
// Per-contact electrical output; see contact_flows.h.
#include "conduction/contact_flows.h"

#include <algorithm>
#include <cmath>

#include "conduction/conductance_laws.h"

namespace ohmdem {

namespace {

const ParticleRecord *find_particle(const std::vector<ParticleRecord> &ps, std::int64_t tag)
{
  auto it = std::lower_bound(ps.begin(), ps.end(), tag,
                             [](const ParticleRecord &p, std::int64_t t) { return p.tag < t; });
  return it != ps.end() && it->tag == tag ? &*it : nullptr;
}

int electrode_of(const ConductionNetwork &net, NodeKey body)
{
  return body == net.high() ? 1 : body == net.low() ? -1 : 0;
}

// Eq. 1 without a constriction: for every spot s of a conducting particle, the sum G_s of the
// eq. 1 conductances joining it to the particle's other spots and the current J_s entering
// the bulk there, J_s = sum_j g_sj (V_s - V_j): the conductances as add_particle_conductances()
// adds them, pair by pair, so the J_s of one particle sum to zero up to rounding.
void bulk_spot_sums(const NetworkScene &scene, const NetworkBuild &built,
                    const ConductionNetwork &net, std::vector<double> &g, std::vector<double> &j)
{
  const auto &spots = built.spots;
  g.assign(spots.size(), 0.0);
  j.assign(spots.size(), 0.0);
  std::vector<double> v(spots.size());
  for (std::size_t s = 0; s < spots.size(); ++s) v[s] = net.potential(spots[s].spot.node);
  for (std::size_t s = 0; s < spots.size();) {
    std::size_t e = s;
    while (e < spots.size() && spots[e].tag == spots[s].tag) ++e;
    const ParticleRecord *p = find_particle(*scene.particles, spots[s].tag);
    if (p && p->member == Membership::None) {
      const double gamma = (*scene.gamma_type)[p->type], volume = sphere_volume(p->radius);
      for (std::size_t a = s; a < e; ++a) {
        const ContactSpot &x = spots[a].spot;
        const double ua[3] = {x.point[0] - p->centre[0], x.point[1] - p->centre[1],
                              x.point[2] - p->centre[2]};
        for (std::size_t b = a + 1; b < e; ++b) {
          const ContactSpot &y = spots[b].spot;
          if (x.node == y.node) continue;  // one electrode: no current inside
          const double ub[3] = {y.point[0] - p->centre[0], y.point[1] - p->centre[1],
                                y.point[2] - p->centre[2]};
          const double gab =
              eq1_conductance(gamma, x.area, y.area, volume, angle_between(ua, ub), p->radius)
                  .conductance;
          if (!(gab > 0.0)) continue;
          const double iab = gab * (v[a] - v[b]);
          g[a] += gab;
          g[b] += gab;
          j[a] += iab;
          j[b] -= iab;
        }
      }
    }
    s = e;
  }
}

}  // namespace

void network_contact_flows(const ConductionModel &model, const NetworkScene &scene,
                           const NetworkBuild &built, const ConductionNetwork &net,
                           std::vector<ContactFlow> &out)
{
  out.clear();
  const auto &contacts = *scene.contacts;
  const auto &spots = built.spots;
  // The two spots of each contact: the owner's (contact.tag) and the other particle's.
  std::vector<int> own(contacts.size(), -1), other(contacts.size(), -1);
  for (std::size_t s = 0; s < spots.size(); ++s) {
    const int k = spots[s].contact;
    if (k < 0) continue;
    (spots[s].tag == contacts[k].tag ? own : other)[k] = static_cast<int>(s);
  }
  std::vector<double> g_bulk, j_bulk;
  const bool constriction = model.has_constriction();
  if (!constriction) bulk_spot_sums(scene, built, net, g_bulk, j_bulk);

  for (std::size_t k = 0; k < contacts.size(); ++k) {
    if (own[k] < 0) continue;  // not a conducting contact
    const ContactRecord &c = contacts[k];
    const ParticleRecord *p = find_particle(*scene.particles, c.tag);
    const ParticleRecord *q = c.race < 0 ? find_particle(*scene.particles, c.other) : nullptr;
    if (!p || (c.race < 0 && !q)) continue;
    ContactFlow row;
    int atom_spot, partner_spot = -1;
    NodeKey partner_body;  // for the electrode column
    if (p->member != Membership::None) {
      // The owner is part of an electrode: the row belongs to the other particle.
      if (!q || q->member != Membership::None) continue;  // inside the electrodes: no row
      row.atom = q->tag;
      atom_spot = other[k];
      partner_spot = own[k];
      partner_body = member_node(p->member);
    } else if (q && q->member == Membership::None) {
      // Two particles: the row belongs to the smaller ID, whichever process saw the contact.
      const bool swap = q->tag < p->tag;
      row.atom = swap ? q->tag : p->tag;
      row.partner = swap ? p->tag : q->tag;
      atom_spot = swap ? other[k] : own[k];
      partner_spot = swap ? own[k] : other[k];
      partner_body = 0;
    } else {
      row.atom = p->tag;
      atom_spot = own[k];
      partner_spot = q ? other[k] : -1;
      partner_body = q ? member_node(q->member) : race_node(c.race);
    }
    if (atom_spot < 0) continue;
    row.electrode = partner_body ? electrode_of(net, partner_body) : 0;
    if (constriction) {
      const double gp = (*scene.gamma_type)[p->type];
      const double go = q ? (*scene.gamma_type)[q->type] : (*scene.gamma_race)[c.race];
      const double rc = model.constriction_resistance(gp, go, c.a, c.b);
      const NodeKey atom_node = spots[atom_spot].spot.node;
      const NodeKey partner_node =
          partner_spot >= 0 ? spots[partner_spot].spot.node : race_node(c.race);
      row.conductance = std::isfinite(rc) && rc > 0.0 ? 1.0 / rc : 0.0;
      row.drop = net.potential(partner_node) - net.potential(atom_node);
      row.current = row.conductance * row.drop;
    } else {
      row.conductance = g_bulk[atom_spot];
      row.current = j_bulk[atom_spot];
      row.drop = row.conductance > 0.0 ? row.current / row.conductance : 0.0;
    }
    out.push_back(row);
  }
}

void ball_between_races_flows(std::int64_t tag, double g_ball, double v, bool constriction,
                              double r_hi, double r_lo, ContactFlow out[2])
{
  const double current = g_ball * v;
  for (int side = 0; side < 2; ++side) {
    ContactFlow &row = out[side];
    row = ContactFlow{};
    row.atom = tag;
    row.electrode = side == 0 ? 1 : -1;
    // Into the ball from the high race, out of it (negative) into the low one.
    row.current = side == 0 ? current : -current;
    const double r = side == 0 ? r_hi : r_lo;
    if (constriction && r > 0.0) {
      row.conductance = 1.0 / r;
      row.drop = row.current * r;
    } else {
      row.conductance = g_ball;
      row.drop = side == 0 ? v : -v;
    }
  }
}

ContactFlow idle_race_flow(std::int64_t tag, int electrode, double constriction_resistance,
                           bool masked)
{
  ContactFlow row;
  row.atom = tag;
  row.electrode = electrode;
  row.masked = masked ? 1 : 0;
  if (!masked && constriction_resistance > 0.0 && std::isfinite(constriction_resistance))
    row.conductance = 1.0 / constriction_resistance;
  return row;
}

}  // namespace ohmdem
