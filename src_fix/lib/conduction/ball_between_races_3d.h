// SPDX-License-Identifier: GPL-2.0-or-later
// One ball between two races in the 3D bearing (plain C++, no LIGGGHTS types): the same model as
// BallBetweenRaces (conduction_model.h), evaluated from the two spots as they are at this step.
// A 3D contact's ellipse changes with its contact angle (contact/torus_race.h), and its spot
// lies off the bearing plane, so neither the areas at 1 N nor the planar angle of the closed
// form hold: eq. 1 takes the angle between the two contact points seen from the ball's centre in
// space, Holm each spot's own ellipse.
#ifndef OHMDEM_BALL_BETWEEN_RACES_3D_H
#define OHMDEM_BALL_BETWEEN_RACES_3D_H

#include "conduction/conduction_model.h"
#include "contact/hertz_contact.h"

namespace ohmdem {

// The resistances (Ohm) of a ball of conductivity gamma and radius r between its spots `hi` and
// `lo` on races of conductivities gamma_hi, gamma_lo, with u, w the vectors from the ball centre
// to the two contact points: the ball's bulk path (eq. 1, 0 without the slot) and each spot's
// constriction (Holm, 0 without the slot). +inf for a zero-size spot or no path.
struct BallResistances3d {
  double bulk = 0, hi = 0, lo = 0;
  double total() const { return bulk + hi + lo; }
};
BallResistances3d ball_resistances_3d(const ConductionModel &model, double gamma, double radius,
                                      double gamma_hi, double gamma_lo, const ContactEllipse &hi,
                                      const ContactEllipse &lo, const double u[3],
                                      const double w[3]);

}  // namespace ohmdem

#endif
