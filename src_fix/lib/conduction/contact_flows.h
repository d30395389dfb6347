// SPDX-License-Identifier: GPL-2.0-or-later
// Per-contact electrical output of a solved conduction model, plain C++ (no LIGGGHTS types):
// one row per conducting contact with the conductance, current and voltage drop of the
// element the contact stands for, oriented from the partner into the atom. The rows satisfy
// Kirchhoff's current law by construction: the currents into a particle sum to zero, those
// out of the high electrode (into the low one) to I. doc/compute_network_resistance.md,
// "Output info"; compute network/resistance's local array.
#ifndef OHMDEM_CONTACT_FLOWS_H
#define OHMDEM_CONTACT_FLOWS_H

#include <cstdint>
#include <vector>

#include "conduction/conduction_model.h"
#include "conduction/network_builder.h"
#include "network/conduction_network.h"

namespace ohmdem {

struct ContactFlow {
  // The columns of the local array, in this order.
  enum Column { kAtom, kPartner, kConductance, kCurrent, kDrop, kMasked, kElectrode, kColumns };

  std::int64_t atom = 0;     // the particle (never an electrode member; of two, the smaller ID)
  std::int64_t partner = 0;  // the other particle; 0 for a race or an electrode
  // The contact's element: with a constriction slot, the constriction across the contact;
  // without one (eq. 1 only), the contact spot's conductance into the atom's bulk, the sum of
  // the eq. 1 conductances joining it to the atom's other spots (S).
  double conductance = 0;
  double current = 0;  // A, through the contact from the partner into the atom
  double drop = 0;     // V, across the element, partner side minus atom side: G drop = current
  int masked = 0;      // 1: a ball–race contact in a defect zone (G = I = drop = 0)
  int electrode = 0;   // the partner is the high (+1) or low (-1) electrode, else 0
};

// Rows of the general network after build_network() and a solve: one per conducting contact
// of scene.contacts (a contact inside one electrode carries no current and has no row).
// `out` is cleared; rows in the order of the contacts.
void network_contact_flows(const ConductionModel &model, const NetworkScene &scene,
                           const NetworkBuild &built, const ConductionNetwork &net,
                           std::vector<ContactFlow> &out);

// The bearing closed form: the two rows of ball `tag` joining the high and the low race, its
// series conductance g_ball, the voltage v between the electrodes (I_ball = g_ball v), and
// its constriction resistances r_hi, r_lo (BallBetweenRaces::constrictions; 0 without a
// constriction slot). The same rows as network_contact_flows() on that ball, to rounding.
void ball_between_races_flows(std::int64_t tag, double g_ball, double v, bool constriction,
                              double r_hi, double r_lo, ContactFlow out[2]);

// A ball touching one race only (a dead end: no current) or a masked contact.
ContactFlow idle_race_flow(std::int64_t tag, int electrode, double constriction_resistance,
                           bool masked);

}  // namespace ohmdem

#endif
