// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/pulse_train.h"

#include <cmath>
#include <limits>

namespace ohmdem::post {

double harmonic_ratio(const FamilyScore &f)
{
  double a[4] = {0, 0, 0, 0};
  for (const Evidence &e : f.evidence)
    for (int h = 1; h <= 3; ++h)
      if (e.label == std::to_string(h) + "x" + f.label) a[h] = e.amplitude;
  if (f.harmonics < 3 || !(a[1] > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (a[2] + a[3]) / (2 * a[1]);
}

bool smooth_modulation(double kurtosis, const FamilyScore &f)
{
  return kurtosis < kSmoothKurtosis && !(harmonic_ratio(f) >= kPulseHarmonics);
}

}  // namespace ohmdem::post
