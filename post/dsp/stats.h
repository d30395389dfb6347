// SPDX-License-Identifier: GPL-2.0-or-later
// Statistical indicators of a signal (paper section 4, plus skewness, impulse and clearance).
#ifndef OHMDEM_POST_STATS_H
#define OHMDEM_POST_STATS_H

#include <cstddef>
#include <vector>

namespace ohmdem::post {

// A simulated signal whose spread std/|mean| lies below this is at the numerical floor of its
// run: the healthy 6208 varies by 3.2e-7 of its mean, a 1-degree inner-race pit by 1.4e-2; 1e-5
// lies three orders of magnitude under the smallest defect's signature.
constexpr double kNumericalFloorSpread = 1e-5;

struct Indicators {
  std::size_t n = 0;
  double peak = 0;  // max |x|
  double mean = 0;
  double rms = 0;        // sqrt(mean x^2)
  double std = 0;        // population standard deviation (ddof = 0, as numpy.std)
  double skewness = 0;   // m3 / m2^1.5 (biased, as scipy.stats.skew)
  double kurtosis = 0;   // m4 / m2^2, Pearson: 3 for a normal law (scipy fisher=False)
  double crest = 0;      // peak / rms
  double shape = 0;      // rms / mean|x|
  double impulse = 0;    // peak / mean|x|
  double clearance = 0;  // peak / (mean sqrt|x|)^2
};

// Two passes with compensated (Neumaier) sums, so values agree with numpy/scipy to ~1e-14.
// Moment ratios of a constant signal (m2 = 0) and factors dividing by zero are NaN: callers
// print them as null / n/a.
Indicators indicators(const double *x, std::size_t n);
inline Indicators indicators(const std::vector<double> &x)
{
  return indicators(x.data(), x.size());
}

// The indicators of the samples [first, last) of a record.
struct WindowIndicators {
  std::size_t first = 0, last = 0;
  Indicators ind;
};

// Windows of `length` samples every `hop` samples from the start (only whole windows), each
// with its own mean removed first when `remove_mean`. length in 2..x.size(), hop >= 1.
std::vector<WindowIndicators> sliding_indicators(const std::vector<double> &x, std::size_t length,
                                                 std::size_t hop, bool remove_mean);

// The indicators of `stats`, in its order: key, definition, dimensionless (no unit suffix in
// CSV column names).
struct IndicatorField {
  const char *key;
  const char *definition;
  bool dimensionless;
  double Indicators::*value;
};
const std::vector<IndicatorField> &indicator_fields();

// Fraction of the samples of a count signal (such as n_masked) that are >= 1 (>= 0.5, so that
// linearly resampled counts are rounded); NaN for an empty signal.
double duty_fraction(const std::vector<double> &count);

}  // namespace ohmdem::post

#endif
