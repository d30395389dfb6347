// SPDX-License-Identifier: GPL-2.0-or-later
// e^z for |z| < 0.25 by its Taylor series to z^13 (z^14/14! < 1e-19): no range reduction. The
// minimum film's power from the central one's (race_admittance.cpp); summed in Estrin's form
// (common/estrin.h), as the four-lane form in race_lane_functions.h does lane by lane.
#ifndef OHMDEM_LUBRICATION_EXP_SMALL_H
#define OHMDEM_LUBRICATION_EXP_SMALL_H

#include "common/estrin.h"

namespace ohmdem::lubrication {

// 1/n!, n = 0 ... 13.
inline constexpr double kExpSmall[14] = {1.0,
                                         1.0,
                                         0.5,
                                         1.0 / 6.0,
                                         1.0 / 24.0,
                                         1.0 / 120.0,
                                         1.0 / 720.0,
                                         1.0 / 5040.0,
                                         1.0 / 40320.0,
                                         1.0 / 362880.0,
                                         1.0 / 3628800.0,
                                         1.0 / 39916800.0,
                                         1.0 / 479001600.0,
                                         1.0 / 6227020800.0};

inline double exp_small(double z)
{
  // 1 + z (1 + z/2 + ...): the last addition alone rounds near 1 (within ~0.8 ulp, as
  // Horner's rule; Estrin's form over all 14 terms gives ~1.7 ulp).
  return 1.0 + z * estrin::polynomial<13>(kExpSmall + 1, z);
}

}  // namespace ohmdem::lubrication

#endif
