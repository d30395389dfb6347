// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/tacho_angle.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.h"
#include "core/error.h"

namespace ohmdem::post {

TachoAngle angle_from_tacho(const std::vector<double> &pulses)
{
  const auto [lo_it, hi_it] = std::minmax_element(pulses.begin(), pulses.end());
  if (pulses.empty() || !(*hi_it > *lo_it))
    throw Error("tachometer column: flat (no once-per-revolution pulses)");
  const double lo = *lo_it, hi = *hi_it;
  const double mid = 0.5 * (lo + hi), armed_below = lo + 0.25 * (hi - lo);
  // the rising edges, in samples
  std::vector<double> edges;
  bool armed = pulses[0] < armed_below;
  for (std::size_t i = 1; i < pulses.size(); ++i) {
    if (pulses[i] < armed_below) armed = true;
    if (armed && pulses[i - 1] < mid && pulses[i] >= mid) {
      edges.push_back(static_cast<double>(i - 1) +
                      (mid - pulses[i - 1]) / (pulses[i] - pulses[i - 1]));
      armed = false;
    }
  }
  if (edges.size() < 2)
    throw Error("tachometer column: " + std::to_string(edges.size()) +
                " once-per-revolution pulse(s) in the record; the angle needs two or more");
  TachoAngle a;
  a.pulses = edges.size();
  a.theta.resize(pulses.size());
  std::size_t k = 0;  // the revolution [edges[k], edges[k + 1]) the sample is read in
  for (std::size_t i = 0; i < pulses.size(); ++i) {
    const double t = static_cast<double>(i);
    while (k + 2 < edges.size() && t >= edges[k + 1]) ++k;
    a.theta[i] = 2 * kPi * (static_cast<double>(k) + (t - edges[k]) / (edges[k + 1] - edges[k]));
  }
  return a;
}

}  // namespace ohmdem::post
