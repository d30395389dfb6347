// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/defect_size.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "dsp/pulses.h"

namespace ohmdem::post {

namespace {

// Fine-tunes the repetition frequency by maximising the synchronous average's contrast.
AveragedPulse best_synchronous(const std::vector<double> &x, double rate, double f)
{
  const double cycles = static_cast<double>(x.size()) * f / rate;
  const double eps = 0.05 / std::max(cycles, 1.0);  // drift of 1/20 period per step
  AveragedPulse best;
  for (int i = -20; i <= 20; ++i) {
    AveragedPulse a = synchronous_pulse(x, rate, f * (1 + i * eps));
    if (a.contrast > best.contrast) best = a;
  }
  return best;
}

}  // namespace

double defect_angle(const std::string &defect, double f, double tau, int nb)
{
  if (defect == "inner" || defect == "outer") return 2 * kPi * f * tau / nb;
  if (defect == "ball") return kPi * f * tau;
  return 0;
}

SizeEstimate estimate_size(const Signal &s, const Diagnosis &d, const BearingGeometry &g)
{
  SizeEstimate e;
  if (d.defect != "inner" && d.defect != "outer" && d.defect != "ball") {
    e.method = "not applicable";
    return e;
  }
  if (!(g.db > 0 && g.dp > 0)) {  // factors only: no race radius to turn a width into a size
    e.method = "needs the ball and pitch diameters (the bearing gives factors only)";
    return e;
  }
  const double f = d.frequency_hz;
  const PulseTrain p = detect_pulses(s.x, s.rate);
  // pulses repeat at the matched frequency (at twice a matched BSF for a ball)
  const double per_pulse = d.defect == "ball" && d.label == "BSF" ? 2 * f : f;
  const bool periodic =
      p.median_spacing_s > 0 && std::fabs(p.median_spacing_s * per_pulse - 1) < 0.1;
  if (p.clean && periodic) {
    e.method = "pulses";
    e.pulse_width_s = p.median_width_s;
    e.pulses = p.counted;
  } else {
    const AveragedPulse a = best_synchronous(s.x, s.rate, per_pulse);
    if (!a.valid) {
      e.method = "no clean pulse train (vibration record or too noisy)";
      return e;
    }
    e.method = "synchronous average";
    e.pulse_width_s = a.width_s;
    e.pulses = a.cycles;
  }
  const double angle = defect_angle(d.defect, per_pulse, e.pulse_width_s, g.nb);
  const double r = d.defect == "ball" ? g.db / 2
                   : d.defect == "inner"
                       ? (g.dp - g.db * std::cos(g.contact_angle_deg * kPi / 180)) / 2
                       : (g.dp + g.db * std::cos(g.contact_angle_deg * kPi / 180)) / 2;
  e.size_deg = angle * 180 / kPi;
  e.arc_m = angle * r;
  e.valid = true;
  return e;
}

}  // namespace ohmdem::post
