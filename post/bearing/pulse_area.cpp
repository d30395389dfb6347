// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/pulse_area.h"

#include <algorithm>
#include <cmath>

#include "bearing/load_zone_fit.h"
#include "core/circular_index.h"
#include "dsp/detect_laws.h"
#include "dsp/pulses.h"
#include "dsp/stats.h"

namespace ohmdem::post {

namespace {

double median(std::vector<double> v)
{
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The pulse's window in the period, as fractions [lo, hi) of it (hi - lo <= 0.6): the folded
// average's bins beyond 2 % of its peak deviation either way (the filter's undershoot belongs
// to the pulse's area), padded by two samples each side.
bool pulse_window(const std::vector<double> &x, double period, double &lo, double &hi,
                  double &centre, double &start)
{
  const auto bins = static_cast<std::size_t>(std::floor(period));
  std::vector<double> sum(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto b = static_cast<std::size_t>(std::fmod(static_cast<double>(i) / period, 1.0) * bins);
    b = std::min(b, bins - 1);
    sum[b] += x[i];
    ++count[b];
  }
  std::vector<double> avg(bins);
  for (std::size_t b = 0; b < bins; ++b) {
    if (count[b] == 0) return false;
    avg[b] = sum[b] / static_cast<double>(count[b]);
  }
  const double base = median(avg);
  std::size_t k = 0;
  for (std::size_t b = 0; b < bins; ++b)
    if (std::fabs(avg[b] - base) > std::fabs(avg[k] - base)) k = b;
  const double peak = avg[k] - base;
  if (peak == 0) return false;
  const auto n = static_cast<long>(bins);
  auto above = [&](long b) {
    return std::fabs(avg[circular_index(b, bins)] - base) >
           0.02 * std::fabs(peak);
  };
  long l = static_cast<long>(k), r = static_cast<long>(k);
  while (above(l - 1) && r - l < n) --l;
  while (above(r + 1) && r - l < n) ++r;
  const double width = static_cast<double>(r - l + 1 + 4);
  if (width > 0.6 * static_cast<double>(bins)) return false;
  lo = static_cast<double>(l - 2) / static_cast<double>(bins);
  start = static_cast<double>(l) / static_cast<double>(bins);  // the first bin beyond 2 %
  hi = lo + width / static_cast<double>(bins);
  // the pulse's centroid (its time plus the filter's delay at 0 Hz): the pass's time. Over the
  // pulse's own sign only: the dip that follows a pit's pulse (the ring settling after the exit,
  // deeper for larger pits) would pull a signed centroid early, by up to 10 deg of shaft for a
  // 3 deg inner pit (doc/methods/size_pulse_area.md, "The inner pit's place and its interval")
  const double sign = peak > 0 ? 1 : -1;
  double m0 = 0, m1 = 0;
  for (long b = l - 2; b <= r + 2; ++b) {
    const double v = std::max((avg[circular_index(b, bins)] - base) * sign, 0.0);
    m0 += v;
    m1 += v * (static_cast<double>(b) + 0.5);
  }
  centre = m1 / m0 / static_cast<double>(bins);
  return true;
}

// Linear interpolation of the size at area a on the model's curve; NaN outside it.
double size_on_curve(const PulseAreaSettings &s, double a)
{
  const std::vector<double> &x = s.curve_rel_area_s, &y = s.curve_size_deg;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (a >= x[i - 1] && a <= x[i])
      return y[i - 1] + (y[i] - y[i - 1]) * (a - x[i - 1]) / (x[i] - x[i - 1]);
  return std::numeric_limits<double>::quiet_NaN();
}

PulseAreaSize from_curve(PulseAreaSize e, const PulseAreaSettings &s, double tq)
{
  if (!std::isfinite(e.window_rel_area_s)) {
    e.note = "the fixed window does not fit the defect's period";
    return e;
  }
  const double a = e.window_rel_area_s;
  double d = tq * e.window_se_s;
  if (s.curve_rel_error > 0) {  // the model's error, as a normal deviate at the same level
    const double z = student_t_isf((1 - s.confidence) / 2, 1e9) * s.curve_rel_error * a;
    d = std::hypot(d, z);
  }
  e.size_deg = size_on_curve(s, a);
  e.size_lo_deg = size_on_curve(s, a - d);
  e.size_hi_deg = size_on_curve(s, a + d);
  if (s.curve_rel_error > 0 && a - d < s.curve_rel_area_s.front())
    e.size_lo_deg = std::max(0.0, s.curve_size_deg.front() * (a - d) / s.curve_rel_area_s.front());
  e.valid = std::isfinite(e.size_deg);
  e.note = e.valid ? "fixed-window pulse area on the model's curve, " + std::to_string(e.passes) +
                         " passes"
                   : "the pulse area lies beyond the model's curve";
  return e;
}

}  // namespace

PassAreas pass_areas(const std::vector<double> &x, double rate, double t0, double f,
                     double level_offset, bool fixed)
{
  PassAreas p;
  const double period = rate / f;
  double lo = 0, hi = 0, centre = 0, start = 0;
  if (period < 4 || !pulse_window(x, period, lo, hi, centre, start)) return p;
  const auto n = static_cast<long>(x.size());
  if (fixed) {
    const auto before = static_cast<long>(std::lround(kWindowBefore * rate));
    const auto after = static_cast<long>(std::lround(kWindowAfter * rate));
    const auto lev = std::max(1L, static_cast<long>(std::lround(kWindowLevel * rate)));
    if (static_cast<double>(before + after + lev) > 0.95 * period) return p;
    for (long j = -1;; ++j) {
      const auto c = static_cast<long>(std::lround((static_cast<double>(j) + start) * period));
      const long a = c - before, b = c + after;
      if (a - lev < 0) continue;
      if (b >= n) break;
      double level = 0, area = 0;
      for (long i = a - lev; i < a; ++i) level += x[static_cast<std::size_t>(i)];
      level /= static_cast<double>(lev);
      for (long i = a; i <= b; ++i) area += x[static_cast<std::size_t>(i)] - level;
      if (level - level_offset == 0) continue;
      p.rel_area.push_back(area / rate / (level - level_offset));
      p.time.push_back(t0 + static_cast<double>(c) / rate);
    }
    return p;
  }
  for (long j = -1;; ++j) {
    const auto a = static_cast<long>(std::ceil((static_cast<double>(j) + lo) * period));
    const auto b = static_cast<long>(std::floor((static_cast<double>(j) + hi) * period));
    const long edge = std::max(2L, (b - a + 1) / 4);  // samples of level each side
    if (a - edge < 0) continue;
    if (b + edge >= n) break;
    double left = 0, right = 0;
    for (long i = 0; i < edge; ++i) {
      left += x[static_cast<std::size_t>(a - edge + i)];
      right += x[static_cast<std::size_t>(b + 1 + i)];
    }
    left /= static_cast<double>(edge);
    right /= static_cast<double>(edge);
    // the level under the pulse: a straight line between the two sides' means
    const double xl = static_cast<double>(a) - 0.5 * static_cast<double>(edge + 1);
    const double xr = static_cast<double>(b) + 0.5 * static_cast<double>(edge + 1);
    double area = 0;
    for (long i = a; i <= b; ++i) {
      const double base = left + (right - left) * (static_cast<double>(i) - xl) / (xr - xl);
      area += x[static_cast<std::size_t>(i)] - base;
    }
    const double level = 0.5 * (left + right) - level_offset;
    if (level == 0) continue;
    p.rel_area.push_back(area / rate / level);
    p.time.push_back(t0 + (static_cast<double>(j) + centre) * period / rate);
  }
  return p;
}

PulseAreaSize size_from_pulse_area(const std::vector<double> &x, double rate, double t0, double f,
                                   const std::string &defect, const PulseAreaSettings &s)
{
  PulseAreaSize e;
  const bool curve = !s.curve_size_deg.empty();
  if (!(s.rel_height > 0) && !curve) {
    e.note = "no model pulse height";
    return e;
  }
  // a level record (R, I R) sits well above zero and jumps up; a vibration record swings about
  // zero: its pulse area means nothing
  const double level = median(x) - s.level_offset;
  if (!(level > 0) || level < 2 * indicators(x).std) {
    e.note = "not a level record (R or I R): the pulse area needs a level well above zero";
    return e;
  }
  const double f_ref = refine_repetition(x, rate, f);
  const PassAreas p = pass_areas(x, rate, t0, f_ref, s.level_offset);
  const std::size_t n = p.rel_area.size();
  e.passes = n;
  const PassAreas w = pass_areas(x, rate, t0, f_ref, s.level_offset, true);
  if (w.rel_area.size() >= 8) {
    double sum = 0, sum2 = 0;
    for (double r : w.rel_area) {
      sum += r;
      sum2 += r * r;
    }
    const double nn = static_cast<double>(w.rel_area.size());
    e.window_rel_area_s = sum / nn;
    e.window_se_s = std::sqrt(std::max(sum2 - sum * sum / nn, 0.0) / (nn - 1) / nn);
  }
  if (n < 8) {
    e.note =
        "fewer than 8 defect passes with a pulse window (rate / pulse frequency < 4, or no "
        "pulse stands out of the level)";
    return e;
  }
  const double tq = student_t_isf((1 - s.confidence) / 2, static_cast<double>(n - 1));
  double c = 0, se = 0;
  if (s.load_zone && defect == "inner") {
    // the defect turns with the shaft: its passes follow the load zone; the peak is the pass
    // at the zone's centre. Each pass when the ball crossed the pit: its pulse less the delay.
    std::vector<double> crossed(p.time);
    for (double &t : crossed) t -= s.delay;
    const ZoneEstimate z =
        zone_estimate(shaft_angles_at(crossed, rate, t0, s.shaft_angle, s.fr), p.rel_area);
    c = z.c;
    se = z.c_se;
    if (s.shaft_angle && !s.shaft_angle->empty()) {
      // the defect meets the load direction when shaft angle + position = load direction
      if (z.c > 0) {
        e.position_deg = wrap_deg(s.load_direction_deg - z.phi_deg);
        e.position_half_deg = tq * z.phi_sd;
      } else {
        e.position_note = "the passes' areas do not follow the load zone";
      }
    }
    e.note = "pulse area, load-zone peak of " + std::to_string(n) + " passes";
  } else {
    double sum = 0, sum2 = 0;
    for (double r : p.rel_area) {
      sum += r;
      sum2 += r * r;
    }
    const double nn = static_cast<double>(n);
    c = sum / nn;
    se = std::sqrt(std::max(sum2 - sum * sum / nn, 0.0) / (nn - 1) / nn);
    e.note = "pulse area, mean of " + std::to_string(n) + " passes";
  }
  e.rel_area_s = c;
  if (curve) return from_curve(e, s, tq);
  e.tau_s = c / s.rel_height;
  e.tau_lo_s = std::max(c - tq * se, 0.0) / s.rel_height;
  e.tau_hi_s = (c + tq * se) / s.rel_height;
  if (s.load_zone && defect == "outer") {
    // the pit's place in the load zone is not known: a smaller jump than the centre's means a
    // longer pulse, so the area gives a lower bound only
    e.tau_hi_s = std::numeric_limits<double>::infinity();
    e.note += "; lower bound (the pit's place in the load zone is not determined)";
  }
  e.valid = e.tau_s > 0;
  if (!e.valid) e.note = "no pulse area (the passes' mean area is not positive)";
  return e;
}

}  // namespace ohmdem::post
