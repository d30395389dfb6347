// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/peaks.h"

#include <algorithm>
#include <cmath>

namespace ohmdem::post {

double amplitude_of(const Spectrum &s, std::size_t k)
{
  const double v = s.value[k];
  switch (s.scaling) {
    case Scaling::Amplitude:
      return v;
    case Scaling::Power:
      return std::sqrt(std::max(v, 0.0));
    case Scaling::Psd:
      return std::sqrt(std::max(v, 0.0));
  }
  return v;
}

namespace {

double from_amplitude(const Spectrum &s, double a, std::size_t k)
{
  if (s.scaling == Scaling::Amplitude) return a;
  // keep the spectrum's own scaling: scale the bin value by the amplitude ratio squared
  const double a0 = amplitude_of(s, k);
  return a0 > 0 ? s.value[k] * (a / a0) * (a / a0) : s.value[k];
}

}  // namespace

std::vector<double> noise_floor(const std::vector<double> &amp, std::size_t block)
{
  const std::size_t n = amp.size();
  std::vector<double> floor(n, 0.0);
  if (n == 0) return floor;
  block = std::max<std::size_t>(4, std::min(block, n));
  const std::size_t hop = std::max<std::size_t>(1, block / 2);
  std::vector<double> centre, median, tmp;
  for (std::size_t start = 0;; start += hop) {
    const std::size_t end = std::min(n, start + block);
    tmp.assign(amp.begin() + static_cast<long>(start), amp.begin() + static_cast<long>(end));
    auto mid = tmp.begin() + static_cast<long>(tmp.size() / 2);
    std::nth_element(tmp.begin(), mid, tmp.end());
    centre.push_back((static_cast<double>(start) + static_cast<double>(end - 1)) / 2);
    median.push_back(*mid);
    if (end == n) break;
  }
  std::size_t j = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double u = static_cast<double>(k);
    while (j + 1 < centre.size() && centre[j + 1] < u) ++j;
    if (j + 1 >= centre.size() || u <= centre[j]) {
      floor[k] = median[std::min(j, median.size() - 1)];
    } else {
      const double a = (u - centre[j]) / (centre[j + 1] - centre[j]);
      floor[k] = median[j] + a * (median[j + 1] - median[j]);
    }
  }
  return floor;
}

std::size_t default_floor_block(const Spectrum &s)
{
  const double pad = static_cast<double>(s.nfft) / static_cast<double>(s.segment);
  return std::max<std::size_t>(16, static_cast<std::size_t>(64 * pad));
}

Peak refine_peak(const Spectrum &s, std::size_t k)
{
  Peak p;
  p.bin = k;
  p.frequency = s.frequency(k);
  p.value = s.value[k];
  const std::size_t nb = s.bins();
  if (k == 0 || k + 1 >= nb) return p;
  const double m0 = amplitude_of(s, k), ml = amplitude_of(s, k - 1), mr = amplitude_of(s, k + 1);
  if (!(m0 > 0) || m0 < ml || m0 < mr) return p;
  const int side = mr >= ml ? 1 : -1;
  const double r = (side > 0 ? mr : ml) / m0;
  const WindowKernel K(s.window, s.segment, s.nfft);
  auto g = [&](double d) { return K(1 - d) / K(d); };
  double d = 0;
  if (r >= 1) {
    d = 0.5;
  } else if (r > g(0)) {
    double lo = 0, hi = 0.5;
    for (int it = 0; it < 60; ++it) {
      const double mid = (lo + hi) / 2;
      (g(mid) < r ? lo : hi) = mid;
    }
    d = (lo + hi) / 2;
  }
  p.frequency = (static_cast<double>(k) + side * d) * s.df;
  p.value = from_amplitude(s, m0 / K(d), k);
  return p;
}

std::vector<Peak> find_peaks(const Spectrum &s, const PeakOptions &opt)
{
  const std::size_t nb = s.bins();
  std::vector<double> amp(nb);
  for (std::size_t k = 0; k < nb; ++k) amp[k] = amplitude_of(s, k);
  const std::vector<double> floor = noise_floor(amp, default_floor_block(s));
  const double top = nb ? *std::max_element(amp.begin(), amp.end()) : 0;
  std::vector<Peak> out;
  for (std::size_t k = 1; k + 1 < nb; ++k) {
    if (!(amp[k] > amp[k - 1] && amp[k] >= amp[k + 1])) continue;
    const double f = s.frequency(k);
    if (f < opt.fmin || f > opt.fmax) continue;
    const double fl = std::max(floor[k], top * 1e-15);
    const double prom = 20 * std::log10(amp[k] / fl);
    if (!(prom >= opt.min_prominence_db)) continue;
    Peak p = opt.interpolate ? refine_peak(s, k) : Peak{f, s.value[k], k, 0};
    p.bin = k;
    p.prominence_db = prom;
    out.push_back(p);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Peak &a, const Peak &b) { return a.value > b.value; });
  if (out.size() > opt.max_peaks) out.resize(opt.max_peaks);
  return out;
}

}  // namespace ohmdem::post
