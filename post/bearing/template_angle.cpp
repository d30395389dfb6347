// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/template_angle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bearing/diagnose.h"
#include "core/circular_index.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

namespace {

const PulseTemplate &find(const std::vector<PulseTemplate> &t, double size, double angle)
{
  for (const PulseTemplate &p : t)
    if (p.size_deg == size && p.angle_deg == angle) return p;
  throw std::invalid_argument("the templates do not cover every size at every angle");
}

}  // namespace

std::vector<PulseTemplate> between_angles(const std::vector<PulseTemplate> &t,
                                          const std::vector<double> &sizes,
                                          const std::vector<double> &angles, int steps,
                                          std::vector<double> &dense)
{
  if (steps < 1) throw std::invalid_argument("between_angles: steps must be >= 1");
  dense.clear();
  for (std::size_t i = 0; i + 1 < angles.size(); ++i)
    for (int k = 0; k < steps; ++k)
      dense.push_back(angles[i] + (angles[i + 1] - angles[i]) * k / steps);
  dense.push_back(angles.back());
  std::vector<PulseTemplate> out;
  for (double s : sizes)
    for (std::size_t i = 0; i < angles.size(); ++i) {
      const PulseTemplate &a = find(t, s, angles[i]);
      out.push_back(a);
      if (i + 1 == angles.size()) continue;
      const PulseTemplate &b = find(t, s, angles[i + 1]);
      // both entries at a quarter of their own bins: b read from its entry on
      const long na = static_cast<long>(a.y.size()), nb = static_cast<long>(b.y.size());
      for (int k = 1; k < steps; ++k) {
        const double u = static_cast<double>(k) / steps;
        PulseTemplate m{s, dense[i * static_cast<std::size_t>(steps) + static_cast<std::size_t>(k)],
                        a.y, a.se};
        for (long j = 0; j < na; ++j) {
          const std::size_t jb = circular_index(j - na / 4 + nb / 4, b.y.size());
          const auto ja = static_cast<std::size_t>(j);
          m.y[ja] = (1 - u) * a.y[ja] + u * b.y[jb];
          m.se[ja] = std::hypot((1 - u) * a.se[ja], u * b.se[jb]);
        }
        out.push_back(std::move(m));
      }
    }
  return out;
}

void pick_branch(DefectLocation &l, const TemplateFit &f)
{
  const std::string fit = "the template fit's angle from the load " +
                          format_number(f.angle_deg, 3) + " deg [" +
                          format_number(f.angle_lo_deg, 3) + ", " +
                          format_number(f.angle_hi_deg, 3) + "]" +
                          (std::isfinite(f.angle_error_deg)
                               ? " (the bank's angle error " + format_number(f.angle_error_deg, 3) +
                                     " deg included)"
                               : "");
  if (!std::isfinite(l.position_modulo_deg) || !std::isfinite(l.position_deg)) {
    l.position_note += "; " + fit + " (either side of the load line)";
    return;
  }
  if (!std::isfinite(f.angle_error_deg)) {
    l.position_note += "; " + fit + ": the bank states no angle error (its '# angle error (deg)'"
                       " line), so the branch is not picked";
    return;
  }
  const double m = l.position_modulo_deg;
  const double plo = std::isfinite(l.position_lo_deg) ? l.position_lo_deg : l.position_deg;
  const double phi = std::isfinite(l.position_hi_deg) ? l.position_hi_deg : l.position_deg;
  std::vector<int> in;
  for (int k = -6; k <= 6; ++k) {
    // the branch's |theta| range: the phase's interval moved by k spacings, folded at 0
    const double a = plo + k * m, b = phi + k * m;
    const double lo = a <= 0 && b >= 0 ? 0 : std::min(std::fabs(a), std::fabs(b));
    const double hi = std::max(std::fabs(a), std::fabs(b));
    if (hi >= f.angle_lo_deg && lo <= f.angle_hi_deg) in.push_back(k);
  }
  if (in.size() != 1) {
    l.position_note += "; " + fit + " meets " + std::to_string(in.size()) +
                       " branches: the branch is not determined";
    return;
  }
  const double k = in[0] * m;
  l.position_deg += k;
  l.position_lo_deg += k;
  l.position_hi_deg += k;
  l.position_modulo_deg = std::nan("");
  l.position_note = "the branch of the pulses' phase (modulo the ball spacing " +
                    format_number(m, 4) + " deg) that meets " + fit +
                    ", positive in the balls' direction of travel";
}

}  // namespace ohmdem::post
