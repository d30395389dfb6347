// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/settle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace ohmdem::post {

namespace {

double median(std::vector<double> v)
{
  const std::size_t h = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h), v.end());
  const double hi = v[h];
  if (v.size() % 2) return hi;
  return 0.5 * (hi + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h)));
}

}  // namespace

Settling settled_start(const std::vector<double> &x, std::size_t window)
{
  if (window < 2) throw Error("settled_start: a window of at least 2 samples, got " +
                              std::to_string(window));
  Settling st;
  const std::size_t n = x.size() / window;
  if (n < 8) return st;
  std::vector<double> m(n);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t j = 0; j < window; ++j) sum += x[i * window + j];
    m[i] = sum / static_cast<double>(window);
  }
  const std::vector<double> tail(m.begin() + static_cast<std::ptrdiff_t>(n / 2), m.end());
  st.level = median(tail);
  std::vector<double> dev(tail.size());
  for (std::size_t i = 0; i < tail.size(); ++i) dev[i] = std::fabs(tail[i] - st.level);
  // a strictly periodic record's windows may agree to the last bits: a floor at the
  // resolution of a double mean
  st.scatter = std::max(1.4826 * median(dev), 64 * std::numeric_limits<double>::epsilon() *
                                                  (1 + std::fabs(st.level)));
  st.first_drift = m[0] - st.level;
  const double limit = kSettleSigmas * st.scatter;
  for (std::size_t i = 0; i <= n / 2; ++i) {
    bool settled = true;
    for (std::size_t j = i; j < i + kSettledWindows && j < n; ++j)
      settled = settled && std::fabs(m[j] - st.level) <= limit;
    if (settled) {
      st.start = i * window;
      return st;
    }
  }
  st.start = (n / 2) * window;
  return st;
}

}  // namespace ohmdem::post
