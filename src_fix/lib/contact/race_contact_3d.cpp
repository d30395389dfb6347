// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/race_contact_3d.h"

#include <stdexcept>

namespace ohmdem {

RaceContactModel3d::RaceContactModel3d(const TorusGroove &groove_, double E_eff, double G_eff,
                                       double G_torsion, double restitution, double friction_)
    : groove(groove_),
      hertz(groove_, E_eff, G_eff, G_torsion),
      beta(restitution_beta(restitution)),
      friction(friction_)
{
  if (!(friction_ >= 0.0)) throw std::invalid_argument("friction coefficient must be >= 0");
}

}  // namespace ohmdem
