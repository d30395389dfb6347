// SPDX-License-Identifier: GPL-2.0-or-later
// Restitution damping; see damping.h.
#include "contact/damping.h"

#include <stdexcept>

#include "common/constants.h"

namespace ohmdem {

double restitution_beta(double restitution)
{
  if (!(restitution > 0.0 && restitution <= 1.0))
    throw std::invalid_argument("coefficient of restitution must be in (0, 1]");
  const double l = std::log(restitution);
  return l / std::sqrt(l * l + kPi * kPi);
}

}  // namespace ohmdem
