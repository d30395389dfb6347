// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/stats.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace ohmdem::post {

namespace {

// Neumaier's compensated sum: the error does not grow with n.
class Sum {
 public:
  void add(double v)
  {
    const double t = s_ + v;
    c_ += std::fabs(s_) >= std::fabs(v) ? (s_ - t) + v : (v - t) + s_;
    s_ = t;
  }
  double value() const { return s_ + c_; }

 private:
  double s_ = 0, c_ = 0;
};

double ratio(double a, double b)
{
  return b != 0 ? a / b : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

Indicators indicators(const double *x, std::size_t n)
{
  Indicators r;
  r.n = n;
  if (n == 0) return r;
  const double dn = static_cast<double>(n);
  Sum s1, sabs, ssqrt, s2raw;
  double peak = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::fabs(x[i]);
    s1.add(x[i]);
    sabs.add(a);
    ssqrt.add(std::sqrt(a));
    s2raw.add(x[i] * x[i]);
    if (a > peak) peak = a;
  }
  const double mean = s1.value() / dn;
  Sum m2, m3, m4;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = x[i] - mean;
    const double d2 = d * d;
    m2.add(d2);
    m3.add(d2 * d);
    m4.add(d2 * d2);
  }
  const double c2 = m2.value() / dn, c3 = m3.value() / dn, c4 = m4.value() / dn;
  const double mabs = sabs.value() / dn, msqrt = ssqrt.value() / dn;
  r.peak = peak;
  r.mean = mean;
  r.rms = std::sqrt(s2raw.value() / dn);
  r.std = std::sqrt(c2);
  // scipy.stats treats m2 <= (1e-15 mean)^2 as a constant input (moment ratios NaN)
  const bool constant = c2 <= std::pow(1e-15 * mean, 2);
  r.skewness = constant ? std::numeric_limits<double>::quiet_NaN() : c3 / std::pow(c2, 1.5);
  r.kurtosis = constant ? std::numeric_limits<double>::quiet_NaN() : c4 / (c2 * c2);
  r.crest = ratio(peak, r.rms);
  r.shape = ratio(r.rms, mabs);
  r.impulse = ratio(peak, mabs);
  r.clearance = ratio(peak, msqrt * msqrt);
  return r;
}

std::vector<WindowIndicators> sliding_indicators(const std::vector<double> &x, std::size_t length,
                                                 std::size_t hop, bool remove_mean)
{
  if (length < 2 || length > x.size() || hop < 1)
    throw Error("sliding windows: " + std::to_string(length) + " samples every " +
                std::to_string(hop) + " over " + std::to_string(x.size()) +
                " (need 2 to the record's length, every >= 1)");
  std::vector<WindowIndicators> out;
  std::vector<double> buf;
  for (std::size_t i0 = 0; i0 + length <= x.size(); i0 += hop) {
    buf.assign(x.begin() + static_cast<long>(i0), x.begin() + static_cast<long>(i0 + length));
    if (remove_mean) {
      const double m = indicators(buf).mean;
      for (double &v : buf) v -= m;
    }
    out.push_back({i0, i0 + length, indicators(buf)});
  }
  return out;
}

const std::vector<IndicatorField> &indicator_fields()
{
  static const std::vector<IndicatorField> fields = {
      {"peak", "max |x|", false, &Indicators::peak},
      {"mean", "mean of x", false, &Indicators::mean},
      {"rms", "sqrt(mean x^2)", false, &Indicators::rms},
      {"std", "population standard deviation (ddof 0)", false, &Indicators::std},
      {"skewness", "m3 / m2^1.5 (biased)", true, &Indicators::skewness},
      {"kurtosis", "m4 / m2^2, Pearson (normal law = 3)", true, &Indicators::kurtosis},
      {"crest", "peak / rms", true, &Indicators::crest},
      {"shape", "rms / mean|x|", true, &Indicators::shape},
      {"impulse", "peak / mean|x|", true, &Indicators::impulse},
      {"clearance", "peak / (mean sqrt|x|)^2", true, &Indicators::clearance},
  };
  return fields;
}

double duty_fraction(const std::vector<double> &count)
{
  if (count.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::size_t on = 0;
  for (double v : count) on += v >= 0.5;
  return static_cast<double>(on) / static_cast<double>(count.size());
}

}  // namespace ohmdem::post
