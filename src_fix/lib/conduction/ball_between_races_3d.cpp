// SPDX-License-Identifier: GPL-2.0-or-later
#include "conduction/ball_between_races_3d.h"

#include <limits>

#include "conduction/conductance_laws.h"

namespace ohmdem {

BallResistances3d ball_resistances_3d(const ConductionModel &model, double gamma, double radius,
                                      double gamma_hi, double gamma_lo, const ContactEllipse &hi,
                                      const ContactEllipse &lo, const double u[3],
                                      const double w[3])
{
  const double inf = std::numeric_limits<double>::infinity();
  BallResistances3d r;
  if (model.has_bulk()) {
    const double g =
        eq1_conductance_between(gamma, hi.area, lo.area, sphere_volume(radius), u, w, radius);
    r.bulk = g > 0.0 ? 1.0 / g : inf;
  }
  r.hi = model.constriction_resistance(gamma, gamma_hi, hi.a, hi.b);
  r.lo = model.constriction_resistance(gamma, gamma_lo, lo.a, lo.b);
  return r;
}

}  // namespace ohmdem
