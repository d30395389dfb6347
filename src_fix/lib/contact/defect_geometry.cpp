// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/defect_geometry.h"

#include <algorithm>
#include <cmath>

#include "common/constants.h"

namespace ohmdem {

double wrap_angle(double a)
{
  a = std::remainder(a, 2.0 * kPi);  // in [-pi, pi]
  return a == -kPi ? kPi : a;
}

double pit_recess(const Pit &pit, double s)
{
  const double d = 0.5 * pit.width - std::fabs(s);
  if (!(d > 0.0)) return 0.0;
  const double r = pit.ball_radius;
  // Resting on the nearer edge; a pit wider than the ball lets it reach the floor.
  const double on_edge = d < r ? r - std::sqrt((r - d) * (r + d)) : r;
  return std::min(pit.depth, on_edge);
}

double pit_max_recess(const Pit &pit)
{
  return pit_recess(pit, 0.0);
}

}  // namespace ohmdem
