// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/event_direction.h"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bearing/diagnose.h"
#include "bearing/pass_energy.h"
#include "bearing/race_sizing.h"
#include "core/constants.h"
#include "core/sampled_signal.h"
#include "dsp/detect_laws.h"

namespace ohmdem::post {

namespace {

// Sums of a window's products about its own means: {first^2, first second, second^2}. The
// window's means are taken off so that the ring's slow swing does not count as an event's.
using Moments = std::array<double, 3>;

Moments window_moments(const std::vector<double> &a, const std::vector<double> &b, std::size_t c,
                       std::size_t half)
{
  double ma = 0, mb = 0;
  for (std::size_t i = c - half; i <= c + half; ++i) ma += a[i], mb += b[i];
  const auto n = static_cast<double>(2 * half + 1);
  ma /= n;
  mb /= n;
  Moments m{0, 0, 0};
  for (std::size_t i = c - half; i <= c + half; ++i) {
    const double da = a[i] - ma, db = b[i] - mb;
    m[0] += da * da;
    m[1] += da * db;
    m[2] += db * db;
  }
  return m;
}

// The principal axis of the symmetric matrix [[m0, m1], [m1, m2]], deg in (-90, 90].
double principal_deg(const Moments &m)
{
  const double a = 0.5 * std::atan2(2 * m[1], m[0] - m[2]) * 180 / kPi;
  return a <= -90 ? a + 180 : a;
}

// a - b as an axis: in (-90, 90].
double axis_difference(double a, double b)
{
  double d = std::fmod(a - b, 180.0);
  if (d > 90) d -= 180;
  if (d <= -90) d += 180;
  return d;
}

}  // namespace

EventDirection event_direction(const std::vector<double> &first, const std::vector<double> &second,
                               double rate, double f, const EventDirectionSettings &s)
{
  PassEnergySettings check;
  check.groups = s.groups;
  check.confidence = s.confidence;
  check_pass_settings(check, rate, f);
  if (first.size() != second.size())
    throw std::invalid_argument("event direction: the two axes hold different numbers of samples");
  if (!(s.model_deg >= 0))
    throw std::invalid_argument("event direction: the model's allowance must be >= 0 deg");
  EventDirection r;
  if (!(f < rate / 8)) {
    r.note = "not determined: the defect frequency must lie below an eighth of the rate";
    return r;
  }
  const std::size_t n = first.size();
  double m1 = 0, m2 = 0;
  for (std::size_t i = 0; i < n; ++i) m1 += first[i], m2 += second[i];
  m1 /= static_cast<double>(n);
  m2 /= static_cast<double>(n);
  // the passes are found on the acceleration's squared magnitude in the plane
  std::vector<double> e(n);
  for (std::size_t i = 0; i < n; ++i)
    e[i] = (first[i] - m1) * (first[i] - m1) + (second[i] - m2) * (second[i] - m2);
  const PassWindows pw = pass_windows(e, rate, f);
  const std::size_t passes = pw.at.size();
  r.passes = passes;
  if (passes < 2 * s.groups) {
    r.note = "not determined: " + std::to_string(passes) + " defect passes in the record, fewer " +
             "than twice the " + std::to_string(s.groups) + " groups of the interval";
    return r;
  }
  // each group's events less its backgrounds
  std::vector<Moments> group(s.groups, Moments{0, 0, 0});
  Moments total{0, 0, 0};
  double background = 0;
  for (std::size_t j = 0; j < passes; ++j) {
    const Moments w = window_moments(first, second, pw.at[j], pw.half);
    const Moments b = window_moments(first, second, pw.background[j], pw.half);
    Moments &g = group[j * s.groups / passes];
    for (int k = 0; k < 3; ++k) {
      g[k] += w[k] - b[k];
      total[k] += w[k] - b[k];
    }
    background += b[0] + b[2];
  }
  const double events = total[0] + total[2];
  // (a 16-bit record below its noise can be flat between the passes: no background at all)
  r.events_to_background = background > 0 ? events / background
                           : events > 0   ? std::numeric_limits<double>::infinity()
                                          : std::nan("");
  // the events must stand out of the background: at least its energy (the windows twice the
  // background's: each window is placed on its pass's strongest stretch, which alone gives
  // noise or a steady tone a ratio of a few tenths), and the groups' event energies, as a
  // sample, significantly above zero
  const auto gn = static_cast<double>(s.groups);
  double mean = 0, var = 0;
  for (const Moments &g : group) mean += (g[0] + g[2]) / gn;
  for (const Moments &g : group) var += std::pow(g[0] + g[2] - mean, 2) / (gn - 1);
  const double t = student_t_isf((1 - s.confidence) / 2, gn - 1);
  const std::string how = std::to_string(passes) + " passes, " +
                          (background > 0 ? "events " + format_number(r.events_to_background, 3) +
                                                " x the background's energy"
                                          : std::string("no energy between the passes"));
  if (!(events > background) || !(mean > t * std::sqrt(var / gn))) {
    r.note = "not determined: no defect events stand out of the background in the two axes (" +
             how + ")";
    return r;
  }
  r.angle_deg = principal_deg(total);
  // jackknife over the groups: the direction with each group left out
  double ss = 0;
  for (const Moments &g : group) {
    const Moments rest{total[0] - g[0], total[1] - g[1], total[2] - g[2]};
    ss += std::pow(axis_difference(principal_deg(rest), r.angle_deg), 2);
  }
  const double sd = std::sqrt((gn - 1) / gn * ss);
  r.half_width_deg = t * sd + s.model_deg;
  r.valid = true;
  r.note = "direction of the defect events in the two axes: " + how;
  return r;
}

void place_outer_by_event_direction(const Signal &s, const RaceToSize &r, const DiagnoseOptions &o,
                                    DefectLocation &l)
{
  if (r.defect != "outer" || !o.across) return;
  if (o.load != "radial") {
    l.position_note = o.load.empty()
                          ? "not determined: needs the load mode ({diagnose.load}, or run.json)"
                          : "not determined: the angle is taken from the load direction, which "
                            "only a radial load has";
    return;
  }
  const EventDirection d = event_direction(s.x, o.across->x, s.rate, r.f, EventDirectionSettings{});
  if (!d.valid) {
    l.position_note = d.note;
    return;
  }
  l.position_deg = d.angle_deg;
  l.position_lo_deg = d.angle_deg - d.half_width_deg;
  l.position_hi_deg = d.angle_deg + d.half_width_deg;
  l.position_modulo_deg = std::nan("");
  l.position_reference = "load direction";
  // the events give a line: a pit more than 90 deg from the load, outside the load zone (where
  // the balls' centrifugal force alone presses the ring), reads 180 deg off
  l.position_note =
      "the events' line, on the load zone's side (a pit beyond 90 deg from the load reads 180 "
      "deg off)";
}

}  // namespace ohmdem::post
