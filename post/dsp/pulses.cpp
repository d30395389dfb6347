// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/pulses.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>

#include "core/constants.h"

namespace ohmdem::post {

namespace {

double median_of(std::vector<double> v)
{
  if (v.empty()) return 0;
  auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double quantile(std::vector<double> v, double q)
{
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double a = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] + a * (v[i + 1] - v[i]) : v[i];
}

struct Run {
  double start, end;  // in samples, interpolated
};

// Runs of y > theta (y already oriented), merged across gaps of <= max_gap samples.
std::vector<Run> runs_above(const std::vector<double> &y, double theta, std::size_t max_gap,
                            bool periodic)
{
  std::vector<Run> runs;
  const std::size_t n = y.size();
  auto cross = [&](std::size_t i) {  // crossing between i-1 and i
    const double a = y[i - 1], b = y[i];
    return static_cast<double>(i - 1) + (b != a ? (theta - a) / (b - a) : 0.5);
  };
  std::size_t i = 0;
  while (i < n) {
    if (!(y[i] > theta)) {
      ++i;
      continue;
    }
    const double s = i > 0 ? cross(i) : (periodic ? -0.5 : 0.0);
    std::size_t j = i;
    while (j < n && y[j] > theta) ++j;
    const double e = j < n ? cross(j) : static_cast<double>(n) - 0.5;
    if (!runs.empty() && s - runs.back().end <= static_cast<double>(max_gap))
      runs.back().end = e;
    else
      runs.push_back({s, e});
    i = j;
  }
  return runs;
}

// Sums of x and x^2 and counts per bin of a fold of `period` samples into sum.size() bins,
// sample i in bin floor(frac(i / period) bins). t - trunc(t) is exact for 0 <= t < 2^52 (it
// equals fmod(t, 1) bit for bit). The bins are found a block at a time, a loop that vectorises
// when I, the integer type of the truncations, is int32 (it must hold i / period and the bin).
template <class I>
void fold_sums(const std::vector<double> &x, double period, std::vector<double> &sum,
               std::vector<double> &sum2, std::vector<std::size_t> &count)
{
  constexpr std::size_t kBlock = 512;
  I bin[kBlock];
  const std::size_t n = x.size(), bins = sum.size();
  const double dbins = static_cast<double>(bins);
  for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
    const auto len = static_cast<I>(std::min(kBlock, n - i0));
    const double first = static_cast<double>(i0);
    for (I j = 0; j < len; ++j) {
      const double t = (first + static_cast<double>(j)) / period;
      const double phase = t - static_cast<double>(static_cast<I>(t));
      bin[j] = static_cast<I>(phase * dbins);
    }
    for (I j = 0; j < len; ++j) {
      const auto b = std::min(static_cast<std::size_t>(bin[j]), bins - 1);
      const double v = x[i0 + static_cast<std::size_t>(j)];
      sum[b] += v;
      sum2[b] += v * v;
      ++count[b];
    }
  }
}

}  // namespace

PulseTrain detect_pulses(const std::vector<double> &x, double rate)
{
  PulseTrain p;
  const std::size_t n = x.size();
  if (n < 16 || !(rate > 0)) return p;
  p.baseline = median_of(x);
  std::vector<double> dev(n);
  for (std::size_t i = 0; i < n; ++i) dev[i] = std::fabs(x[i] - p.baseline);
  p.noise = 1.4826 * median_of(dev);
  const double floor_noise = 1e-12 * (std::fabs(p.baseline) + 1);
  const double sigma = std::max(p.noise, floor_noise);
  // plateau height: median of the outliers of the dominant polarity
  std::vector<double> up, down;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = x[i] - p.baseline;
    if (d > 6 * sigma) up.push_back(d);
    if (d < -6 * sigma) down.push_back(-d);
  }
  const bool positive = up.size() >= down.size();
  const std::vector<double> &out = positive ? up : down;
  if (out.size() < 3) return p;
  const double h = median_of(out);
  p.height = positive ? h : -h;
  const double theta = h / 2;
  if (!(theta > 3 * sigma)) return p;
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = (positive ? 1 : -1) * (x[i] - p.baseline);
  const auto runs = runs_above(y, theta, 2, false);
  std::vector<double> widths, starts;
  for (const Run &r : runs) {
    p.start_s.push_back(r.start / rate);
    p.width_s.push_back((r.end - r.start) / rate);
    if (r.end - r.start >= 3) {
      widths.push_back((r.end - r.start) / rate);
      starts.push_back(r.start / rate);
    }
  }
  p.counted = widths.size();
  if (p.counted == 0) return p;
  p.median_width_s = median_of(widths);
  p.width_spread = (quantile(widths, 0.75) - quantile(widths, 0.25)) / p.median_width_s;
  std::vector<double> gaps;
  for (std::size_t k = 1; k < starts.size(); ++k) gaps.push_back(starts[k] - starts[k - 1]);
  p.median_spacing_s = median_of(gaps);
  p.clean = p.counted >= 3 && p.width_spread < 0.25 && h > 6 * sigma;
  return p;
}

AveragedPulse synchronous_pulse(const std::vector<double> &x, double rate, double f)
{
  AveragedPulse a;
  const std::size_t n = x.size();
  if (!(f > 0) || !(rate > 0) || n < 16) return a;
  const double period = rate / f;  // samples
  const auto bins = static_cast<std::size_t>(std::floor(period));
  if (bins < 8) return a;
  a.cycles = static_cast<std::size_t>(static_cast<double>(n) / period);
  if (a.cycles < 4) return a;
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0);
  std::vector<std::size_t> count(bins, 0);
  // refine_repetition folds the record 41 times: the fold is the hot loop of diagnose's size
  constexpr double kInt32 = 2147483647.0;
  if (static_cast<double>(n) / period < kInt32 && static_cast<double>(bins) < kInt32)
    fold_sums<std::int32_t>(x, period, sum, sum2, count);
  else
    fold_sums<std::int64_t>(x, period, sum, sum2, count);
  std::vector<double> avg(bins);
  double var = 0;
  std::size_t nvar = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    if (count[b] == 0) return a;
    avg[b] = sum[b] / static_cast<double>(count[b]);
    if (count[b] > 1) {
      const double v = (sum2[b] / static_cast<double>(count[b]) - avg[b] * avg[b]) /
                       static_cast<double>(count[b] - 1);
      var += std::max(v, 0.0);
      ++nvar;
    }
  }
  const double base = median_of(avg);
  double peak = 0;
  std::size_t ipeak = 0;
  for (std::size_t b = 0; b < bins; ++b)
    if (std::fabs(avg[b] - base) > std::fabs(peak)) {
      peak = avg[b] - base;
      ipeak = b;
    }
  // noise of the average: residual scatter per bin / sqrt(samples per bin), or the spread of
  // the averaged waveform away from the pulse (whichever is larger)
  const double noise_avg = nvar ? std::sqrt(var / static_cast<double>(nvar)) : 0;
  std::vector<double> dev(bins);
  for (std::size_t b = 0; b < bins; ++b) dev[b] = std::fabs(avg[b] - base);
  const double spread = 1.4826 * median_of(dev);
  const double noise = std::max({noise_avg, spread, 1e-12 * (std::fabs(base) + 1)});
  a.height = peak;
  a.contrast = std::fabs(peak) / noise;
  // rotate so the pulse sits in the middle, then measure its width at half height
  std::vector<double> y(bins);
  const std::size_t shift = (ipeak + bins - bins / 2) % bins;
  for (std::size_t b = 0; b < bins; ++b)
    y[b] = (peak > 0 ? 1 : -1) * (avg[(b + shift) % bins] - base);
  const auto runs = runs_above(y, std::fabs(peak) / 2, 0, true);
  const double centre = static_cast<double>(bins / 2);
  for (const Run &r : runs)
    if (r.start <= centre + 1 && r.end >= centre - 1) {
      // bin width in samples is period / bins
      a.width_s = (r.end - r.start) * (period / static_cast<double>(bins)) / rate;
      break;
    }
  a.valid = a.contrast >= 6 && a.width_s * rate >= 2;
  return a;
}

double refine_repetition(const std::vector<double> &x, double rate, double f)
{
  const double cycles = static_cast<double>(x.size()) * f / rate;
  const double eps = 0.05 / std::max(cycles, 1.0);  // drift of 1/20 period per step
  double best_f = f, best = -1;
  for (int i = -20; i <= 20; ++i) {
    const double fi = f * (1 + i * eps);
    const AveragedPulse a = synchronous_pulse(x, rate, fi);
    if (a.contrast > best) {
      best = a.contrast;
      best_f = fi;
    }
  }
  return best_f;
}

namespace {

// sum over k = 1..harmonics of |sum_i v_i exp(-2 pi i k f i / rate)|^2; the phasors advanced by
// recurrence and reset from the exact phase every 1024 samples (rounding stays ~1e-13)
double harmonic_power(const std::vector<double> &v, double rate, double f, int harmonics)
{
  constexpr std::size_t kReset = 1024;
  const double step = 2 * kPi * f / rate;
  double power = 0;
  for (int k = 1; k <= harmonics; ++k) {
    const std::complex<double> w = std::polar(1.0, -step * k);
    std::complex<double> acc = 0;
    for (std::size_t i0 = 0; i0 < v.size(); i0 += kReset) {
      // the phase modulo one turn before the product, so that it stays exact for long records
      const double cycles =
          std::fmod(static_cast<double>(k) * f / rate * static_cast<double>(i0), 1.0);
      std::complex<double> z = std::polar(1.0, -2 * kPi * cycles);
      const std::size_t end = std::min(v.size(), i0 + kReset);
      for (std::size_t i = i0; i < end; ++i) {
        acc += v[i] * z;
        z *= w;
      }
    }
    power += std::norm(acc);
  }
  return power;
}

}  // namespace

double refine_repetition_fine(const std::vector<double> &x, double rate, double f, double max_hz)
{
  if (x.empty() || !(rate > 0) || !(f > 0)) return f;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> v(x.size());
  double spread = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    v[i] = x[i] - mean;
    spread = std::max(spread, std::fabs(v[i]));
  }
  // a flat record (to its mean's rounding) has no repetition to refine: f is kept
  if (!(spread > 1e-12 * std::fabs(mean))) return f;
  const int harmonics = std::clamp(static_cast<int>(std::floor(max_hz / f)), 1, 32);
  const double cycles = static_cast<double>(x.size()) * f / rate;
  const double eps = 0.05 / std::max(cycles, 1.0);  // refine_repetition's step
  // three grids of 41, each 20 times finer around the last one's best: the first spans the
  // main lobe of every harmonic used (1/(k cycles) >= eps 20/32), the last steps 2.5e-4 eps
  double best_f = f;
  double span = 2 * eps;
  for (int stage = 0; stage < 3; ++stage, span /= 20) {
    const double centre = best_f;
    double best = harmonic_power(v, rate, centre, harmonics);
    for (int i = -20; i <= 20; ++i) {
      const double fi = centre * (1 + span * i / 20);
      const double p = i == 0 ? best : harmonic_power(v, rate, fi, harmonics);
      if (p > best) best = p, best_f = fi;
    }
  }
  return best_f;
}

}  // namespace ohmdem::post
