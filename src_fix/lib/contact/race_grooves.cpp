// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/race_grooves.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"

namespace ohmdem {

GrooveCircle groove_circle(RaceSide side, double R, double Rc, double r, double clearance,
                           double alpha0)
{
  if (!(clearance >= 0.0)) throw std::invalid_argument("clearance must be >= 0 m");
  if (!(alpha0 >= 0.0 && alpha0 < 0.5 * kPi))
    throw std::invalid_argument("the nominal contact angle alpha0 must be in [0, 90) degrees");
  if (clearance > 0.0 && alpha0 > 0.0)
    throw std::invalid_argument(
        "give a clearance (deep-groove bearing) or a nominal contact angle alpha0 "
        "(angular-contact bearing), not both");
  if (!(Rc > r)) throw std::invalid_argument("groove radius must be larger than the ball radius");
  const bool inner = side == RaceSide::Inner;
  GrooveCircle g;
  if (alpha0 > 0.0) {
    const double s = inner ? 1.0 : -1.0;
    g.centre_radius = R + s * (r + (Rc - r) * std::cos(alpha0));
    g.centre_z = s * (Rc - r) * std::sin(alpha0);
  } else {
    g.centre_radius = inner ? R + Rc - 0.25 * clearance : R - Rc + 0.25 * clearance;
  }
  return g;
}

double free_contact_angle(double clearance, double A)
{
  if (!(A > 0.0)) throw std::invalid_argument("the grooves must be larger than the ball");
  const double c = 1.0 - clearance / (2.0 * A);
  if (!(c > 0.0))
    throw std::invalid_argument("a clearance of " + std::to_string(clearance) +
                                " m lets the ball pass between the grooves (it must be below "
                                "2 (Rci + Rco - Db) = " +
                                std::to_string(2.0 * A) + " m)");
  return std::acos(c > 1.0 ? 1.0 : c);
}

}  // namespace ohmdem
