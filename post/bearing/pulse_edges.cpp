// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/pulse_edges.h"

#include <algorithm>
#include <cmath>

#include "dsp/pulses.h"

namespace ohmdem::post {

double folded_edge_width(const std::vector<double> &x, std::size_t from, std::size_t to,
                         double period, double rate)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto bins = static_cast<std::size_t>(std::floor(period * kEdgeOversample));
  if (bins < 4 * kEdgeOversample || to <= from) return nan;
  std::vector<double> sum(bins, 0.0);
  std::vector<double> count(bins, 0.0);
  for (std::size_t i = from; i < to; ++i) {
    const double u = std::fmod(static_cast<double>(i) / period, 1.0);
    const auto b = std::min(static_cast<std::size_t>(u * static_cast<double>(bins)), bins - 1);
    sum[b] += x[i];
    count[b] += 1;
  }
  // a box of one sample (kEdgeOversample bins): every box holds samples of several passes
  std::vector<double> avg(bins);
  double s = 0, c = 0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kEdgeOversample); ++k) {
    s += sum[k];
    c += count[k];
  }
  for (std::size_t b = 0; b < bins; ++b) {
    if (c == 0) return nan;
    avg[b] = s / c;
    const std::size_t out = b, in = (b + kEdgeOversample) % bins;
    s += sum[in] - sum[out];
    c += count[in] - count[out];
  }
  // the rise over one sample: a per-bin difference would only amplify the fold's noise
  std::vector<double> d(bins);
  for (std::size_t b = 0; b < bins; ++b) d[b] = avg[(b + kEdgeOversample) % bins] - avg[b];
  const std::size_t entry =
      static_cast<std::size_t>(std::max_element(d.begin(), d.end()) - d.begin());
  if (!(d[entry] > 0)) return nan;
  // the entry's sub-bin place: the vertex of the parabola through the peak and its neighbours
  const double dm = d[(entry + bins - 1) % bins], dp = d[(entry + 1) % bins];
  const double curv = dm - 2 * d[entry] + dp;
  const double at_entry = curv < 0 ? 0.5 * (dm - dp) / curv : 0.0;
  const auto span = static_cast<std::size_t>(0.6 * static_cast<double>(bins));
  double fall = 0;
  for (std::size_t k = 1; k <= span; ++k) fall = std::min(fall, d[(entry + k) % bins]);
  if (!(fall < 0)) return nan;
  // the exit: the last bin below the threshold, and where the fall crosses it after that bin
  const double th = kExitFall * fall;
  double exit = 0;
  for (std::size_t k = 1; k < span; ++k) {
    const double a = d[(entry + k) % bins], b = d[(entry + k + 1) % bins];
    if (a < th && b >= th) exit = static_cast<double>(k) + (th - a) / (b - a);
  }
  if (exit == 0) return nan;
  return (exit - at_entry) * period / static_cast<double>(bins) / rate;
}

CurveReading read_on_curve(const std::vector<double> &sizes, const std::vector<double> &values,
                           double v, double d)
{
  const auto at = [&](double a) {
    for (std::size_t i = 1; i < values.size(); ++i)
      if (a >= values[i - 1] && a <= values[i])
        return sizes[i - 1] +
               (sizes[i] - sizes[i - 1]) * (a - values[i - 1]) / (values[i] - values[i - 1]);
    return std::numeric_limits<double>::quiet_NaN();
  };
  CurveReading r;
  r.size = at(v);
  r.lo = v - d < values.front() ? sizes.front() * std::max(v - d, 0.0) / values.front() : at(v - d);
  r.hi = at(v + d);
  return r;
}

PulseEdges pulse_edge_width(const std::vector<double> &x, double rate, double f)
{
  PulseEdges e;
  const double period = rate / refine_repetition(x, rate, f);
  const double passes = static_cast<double>(x.size()) / period;
  if (!(period >= 4) || passes < 4 * kEdgeBlocks) {
    e.note = "fewer than " + std::to_string(4 * kEdgeBlocks) +
             " defect passes, or fewer than 4 samples per period";
    return e;
  }
  e.width_s = folded_edge_width(x, 0, x.size(), period, rate);
  if (!std::isfinite(e.width_s)) {
    e.note = "no entry and exit edges in the folded pulse";
    return e;
  }
  // the standard error from contiguous blocks of the record, each folded alone
  std::vector<double> w;
  const std::size_t n = x.size() / kEdgeBlocks;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kEdgeBlocks); ++k) {
    const double v = folded_edge_width(x, k * n, (k + 1) * n, period, rate);
    if (std::isfinite(v)) w.push_back(v);
  }
  if (w.size() < 4) {
    e.note = "fewer than 4 blocks of the record show the pulse's edges";
    return e;
  }
  double m = 0, m2 = 0;
  for (double v : w) m += v;
  m /= static_cast<double>(w.size());
  for (double v : w) m2 += (v - m) * (v - m);
  const double nb = static_cast<double>(w.size());
  e.se_s = std::sqrt(m2 / (nb - 1) / nb);
  e.blocks = w.size();
  e.valid = true;
  return e;
}

}  // namespace ohmdem::post
