// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/outer_position.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "dsp/detect_laws.h"

namespace ohmdem::post {

namespace {

double wrap(double a)  // to [-pi, pi)
{
  return a - 2 * kPi * std::floor((a + kPi) / (2 * kPi));
}

// Weighted least squares of y = c0 + c1 cos u + c2 sin u over the bins kept: the normal
// equations (3 x 3) by Cramer's rule. False when singular.
bool fit_fundamental(const std::vector<double> &y, const std::vector<double> &w,
                     const std::vector<bool> &keep, double c[3])
{
  double a[3][3] = {}, b[3] = {};
  const auto n = y.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (!keep[k]) continue;
    const double u = 2 * kPi * (static_cast<double>(k) + 0.5) / static_cast<double>(n);
    const double v[3] = {1, std::cos(u), std::sin(u)};
    for (int i = 0; i < 3; ++i) {
      b[i] += w[k] * v[i] * y[k];
      for (int j = 0; j < 3; ++j) a[i][j] += w[k] * v[i] * v[j];
    }
  }
  const auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  if (!(std::fabs(d) > 0)) return false;
  for (int col = 0; col < 3; ++col) {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == col ? b[i] : a[i][j];
    c[col] = det(m) / d;
  }
  return true;
}

}  // namespace

FoldPhases fold_phases(const std::vector<double> &x, std::size_t from, std::size_t to, double rate,
                       double f)
{
  FoldPhases r;
  const std::size_t n = kPhaseBins;
  std::vector<double> sum(n, 0.0), count(n, 0.0);
  for (std::size_t i = from; i < to && i < x.size(); ++i) {
    const double u = std::fmod(static_cast<double>(i) * f / rate, 1.0);
    const auto b = std::min(static_cast<std::size_t>(u * static_cast<double>(n)), n - 1);
    sum[b] += x[i];
    count[b] += 1;
  }
  std::vector<double> avg(n);
  for (std::size_t b = 0; b < n; ++b) {
    if (count[b] == 0) return r;
    avg[b] = sum[b] / count[b];
  }
  std::vector<double> sorted = avg;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double level = sorted[n / 2];
  const auto peak =
      static_cast<std::size_t>(std::max_element(avg.begin(), avg.end()) - avg.begin());
  const double top = avg[peak] - level;
  if (!(top > 0) || !(level != 0)) return r;
  // the pulse's centroid: the bins around the peak above kCentroidLevel of it, weighted by
  // their rise (a circular mean: the pulse may straddle the fold's ends)
  double cx = 0, cy = 0;
  const auto add = [&](std::size_t b) {
    const double u = 2 * kPi * (static_cast<double>(b) + 0.5) / static_cast<double>(n);
    cx += (avg[b] - level) * std::cos(u);
    cy += (avg[b] - level) * std::sin(u);
  };
  add(peak);
  for (std::size_t k = 1; k < n / 2 && avg[(peak + k) % n] - level > kCentroidLevel * top; ++k)
    add((peak + k) % n);
  for (std::size_t k = 1; k < n / 2 && avg[(peak + n - k) % n] - level > kCentroidLevel * top; ++k)
    add((peak + n - k) % n);
  r.pulse = std::atan2(cy, cx);
  // the smooth modulation away from the pulse (and the ringing after it)
  std::vector<bool> keep(n);
  for (std::size_t b = 0; b < n; ++b) {
    const double u = 2 * kPi * (static_cast<double>(b) + 0.5) / static_cast<double>(n);
    keep[b] = std::fabs(wrap(u - r.pulse)) > 2 * kPi * kPulseMask;
  }
  double c[3];
  if (!fit_fundamental(avg, count, keep, c) || !(std::hypot(c[1], c[2]) > 0)) return r;
  // a pulse, not the modulation's own crest: a healthy record's fold peaks at its maximum
  if (!(top > kPulseOverModulation * std::hypot(c[1], c[2]))) return r;
  r.modulation = std::atan2(c[2], c[1]);
  r.rel_amplitude = std::hypot(c[1], c[2]) / std::fabs(c[0]);
  r.valid = true;
  return r;
}

OuterPosition outer_position(const std::vector<double> &x, double rate, double f, int nb,
                             double crossing_s)
{
  OuterPosition p;
  if (!(rate > 0 && f > 0 && f < rate / 2 && nb >= 2)) {
    p.note = "no ball-pass frequency below the Nyquist frequency, or too few balls";
    return p;
  }
  p.spacing_deg = 360.0 / nb;
  // each block spans enough passes to fill the fold's bins several times over
  constexpr double kMinCyclesPerBlock = 6;
  const double cycles = static_cast<double>(x.size()) * f / rate;
  if (cycles < kMinCyclesPerBlock * kPhaseBlocks) {
    p.note = "too few ball passes for the phase (" + std::to_string(static_cast<int>(cycles)) +
             ", needs " + std::to_string(static_cast<int>(kMinCyclesPerBlock * kPhaseBlocks)) + ")";
    return p;
  }
  const FoldPhases all = fold_phases(x, 0, x.size(), rate, f);
  if (!all.valid) {
    p.note = "no pulse above the level and the ball-pass modulation in the fold";
    return p;
  }
  const double lag = wrap(all.pulse - all.modulation);
  double ss = 0;
  for (int b = 0; b < kPhaseBlocks; ++b) {
    const std::size_t from = x.size() * b / kPhaseBlocks, to = x.size() * (b + 1) / kPhaseBlocks;
    const FoldPhases q = fold_phases(x, from, to, rate, f);
    if (!q.valid) {
      p.note = "a block of the record has no pulse or no modulation";
      return p;
    }
    ss += std::pow(wrap(q.pulse - q.modulation - lag), 2);
  }
  p.blocks = kPhaseBlocks;
  const double se = std::sqrt(ss / (kPhaseBlocks - 1) / kPhaseBlocks);  // rad of the BPFO cycle
  // the lag must stand out of its scatter (an amplitude some 6 times its noise): else the
  // record holds no load-zone modulation and the phase would be the noise's
  constexpr double kMaxPhaseSe = 10 * kPi / 180;
  if (!(se < kMaxPhaseSe)) {
    p.note = "the ball-pass modulation's phase is not measurable (standard error " +
             std::to_string(static_cast<int>(se * 180 / kPi)) + " deg of the cycle)";
    return p;
  }
  const double to_deg = 180 / kPi / nb;  // BPFO phase (rad) -> angle on the race (deg)
  p.angle_deg = lag * to_deg;            // the branch nearest the load direction
  p.se_deg = se * to_deg;
  // the centroid of a pulse whose height changes along the crossing lies anywhere within it
  const double half_crossing = std::isfinite(crossing_s) ? 0.5 * 360 * f / nb * crossing_s : 0;
  p.half_width_deg = std::hypot(student_t_isf(0.025, kPhaseBlocks - 1) * p.se_deg,
                                normal_isf(0.025) * kSystematicDeg) +
                     half_crossing;
  p.rel_modulation = all.rel_amplitude;
  p.valid = true;
  return p;
}

}  // namespace ohmdem::post
