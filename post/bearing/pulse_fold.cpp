// SPDX-License-Identifier: GPL-2.0-or-later
// The record folded at the defect's period (pulse_template.h): the passes' mean pulse and its
// error per fine bin, aligned at the entry. The fit of the bank to it is pulse_template.cpp's.
#include "bearing/pulse_template.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/circular_index.h"
#include "dsp/pulses.h"

namespace ohmdem::post {

namespace {

// Fewer passes leave a fine bin with a handful of samples: its scatter would not be its error.
constexpr std::size_t kMinPasses = 32;

}  // namespace

FoldedPulse fold_pulse(const std::vector<double> &x, double rate, double f, int oversample,
                       FoldPeriod how)
{
  if (!(rate > 0 && f > 0 && oversample >= 1))
    throw std::invalid_argument("pulse fold: rate, defect frequency and oversampling must be > 0");
  FoldedPulse p;
  double level = 0;
  for (double v : x) level += v;
  level /= static_cast<double>(std::max<std::size_t>(x.size(), 1));
  if (!(level > 0)) {
    p.note = "the record's level is not above zero (a vibration channel?): the pulses are read "
             "relative to it";
    return p;
  }
  const double f_grid = refine_repetition(x, rate, f);
  // fine: the harmonics below 0.4 rate (an acquisition chain's anti-alias cut-off)
  const double period =
      rate / (how == FoldPeriod::fine ? refine_repetition_fine(x, rate, f_grid, 0.4 * rate)
                                      : f_grid);  // samples
  const auto bins = static_cast<std::size_t>(std::floor(period * oversample));
  p.passes = static_cast<std::size_t>(static_cast<double>(x.size()) / period);
  if (!(period >= 4) || p.passes < kMinPasses) {
    p.note = std::to_string(p.passes) + " defect passes, fewer than " +
             std::to_string(kMinPasses) + " (or under 4 samples per period)";
    return p;
  }
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0), n(bins, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double u = std::fmod(static_cast<double>(i) / period, 1.0);
    const auto b = std::min(static_cast<std::size_t>(u * static_cast<double>(bins)), bins - 1);
    const double v = x[i] / level - 1;
    sum[b] += v;
    sum2[b] += v * v;
    n[b] += 1;
  }
  std::vector<double> y(bins, 0.0), se(bins, 0.0);
  std::size_t empty = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    if (n[b] < 2) {
      ++empty;
      continue;
    }
    y[b] = sum[b] / n[b];
    se[b] = std::sqrt(std::max(sum2[b] - n[b] * y[b] * y[b], 0.0) / (n[b] - 1) / n[b]);
  }
  // a period close to a whole number of samples leaves sub-sample phases no pass fell at (the
  // 6208's BPFI at 10 kHz: 16.0 samples)
  if (2 * empty > bins) {
    p.note = "the passes cover under half the period's sub-sample phases (a period of a near "
             "whole number of samples)";
    return p;
  }
  // a quantised, noiseless bin would weigh without bound: no bin's error below a tenth of the
  // median's
  std::vector<double> sorted;
  for (std::size_t b = 0; b < bins; ++b)
    if (n[b] >= 2) sorted.push_back(se[b]);
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double floor_se = std::max(0.1 * sorted[sorted.size() / 2], 1e-12);
  for (double &v : se) v = std::max(v, floor_se);
  // an empty bin: the line between its filled neighbours, weighing nothing in a fit
  double big = 0;
  for (std::size_t b = 0; b < bins; ++b)
    if (n[b] >= 2) big = std::max(big, kEmptyBinErrorFactor * se[b]);
  for (std::size_t b = 0; b < bins; ++b) {
    if (n[b] >= 2) continue;
    std::size_t l = 1, r = 1;
    while (n[(b + bins - l) % bins] < 2) ++l;
    while (n[(b + r) % bins] < 2) ++r;
    y[b] = (static_cast<double>(r) * y[(b + bins - l) % bins] +
            static_cast<double>(l) * y[(b + r) % bins]) /
           static_cast<double>(l + r);
    se[b] = big;
  }
  // the entry: the largest rise over one sample of the fold smoothed over one sample (the ball's
  // path lost: R jumps up), at the middle of that rise
  const auto os = static_cast<std::size_t>(oversample);
  std::vector<double> sm(bins, 0.0);
  for (std::size_t b = 0; b < bins; ++b)
    for (std::size_t k = 0; k < os; ++k) sm[b] += y[(b + k) % bins] / static_cast<double>(os);
  std::size_t entry = 0;
  double rise = -1e300;
  for (std::size_t b = 0; b < bins; ++b) {
    const double d = sm[(b + os) % bins] - sm[b];
    if (d > rise) rise = d, entry = (b + os / 2 + os / 2) % bins;
  }
  p.entry = bins / 4;
  p.y.resize(bins);
  p.se.resize(bins);
  for (std::size_t j = 0; j < bins; ++j) {
    const std::size_t b = circular_index(static_cast<long>(entry + j) - static_cast<long>(p.entry), bins);
    p.y[j] = y[b];
    p.se[j] = se[b];
  }
  p.empty = empty;
  p.bin_s = 1 / (rate * oversample);
  p.period_s = period / rate;
  p.how = how;
  p.valid = true;
  return p;
}

std::size_t bins_without_passes(const std::vector<double> &se)
{
  if (se.empty()) return 0;
  const double top = *std::max_element(se.begin(), se.end());
  // the empty bins all at the top (one value, to the digits a file keeps), every other at most
  // 1/kEmptyBinErrorFactor of it (by a factor of 2); a bin between makes it a filled fold's range
  std::size_t high = 0, low = 0;
  for (double v : se) {
    if (v >= (1 - 1e-3) * top) ++high;
    else if (v <= 2 * top / kEmptyBinErrorFactor) ++low;
  }
  return low > 0 && high + low == se.size() ? high : 0;
}

}  // namespace ohmdem::post

