// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/cage_contact.h"

#include <stdexcept>

namespace ohmdem {

CageContactModel::CageContactModel(double ball_radius_, double clearance_, double E_eff,
                                   double restitution)
    : ball_radius(ball_radius_),
      clearance(clearance_),
      hertz(sphere_flat(ball_radius_), E_eff, AreaModel::Exact),
      beta(restitution_beta(restitution))
{
  if (!(clearance_ >= 0.0)) throw std::invalid_argument("pocket clearance must be >= 0");
}

}  // namespace ohmdem
