// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/order_tracking.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

namespace {

constexpr double kBeta = 10.0;         // Kaiser shape: ~100 dB stopband
constexpr double kZeroCrossings = 16;  // kernel half-length in zero crossings of the sinc

// Kaiser window w(u) = I0(beta sqrt(1 - u^2)) / I0(beta) on u in [0, 1], tabulated (linear
// interpolation between 4096 intervals: error < 1e-7, far below the window's own ripple).
class KaiserTable {
 public:
  KaiserTable()
  {
    const double norm = std::cyl_bessel_i(0.0, kBeta);
    for (std::size_t i = 0; i < w_.size(); ++i) {
      const double u = static_cast<double>(i) / (w_.size() - 1);
      w_[i] = std::cyl_bessel_i(0.0, kBeta * std::sqrt(std::max(0.0, 1 - u * u))) / norm;
    }
  }
  double operator()(double u) const
  {
    u = std::fabs(u);
    if (u >= 1) return 0;
    const double p = u * static_cast<double>(w_.size() - 1);
    const auto i = static_cast<std::size_t>(p);
    const double f = p - static_cast<double>(i);
    return w_[i] + f * (w_[i + 1] - w_[i]);
  }

 private:
  std::array<double, 4097> w_{};
};

double sinc(double x)
{
  if (std::fabs(x) < 1e-12) return 1;
  return std::sin(kPi * x) / (kPi * x);
}

}  // namespace

SpeedUnit parse_speed_unit(const std::string &name)
{
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  if (n == "rad/s") return SpeedUnit::RadPerS;
  if (n == "rpm") return SpeedUnit::Rpm;
  if (n == "hz") return SpeedUnit::Hz;
  throw SettingError("option {orders.speed_unit} expects rad/s|rpm|hz, got '" + name + "'");
}

const char *speed_unit_name(SpeedUnit u)
{
  switch (u) {
    case SpeedUnit::RadPerS:
      return "rad/s";
    case SpeedUnit::Rpm:
      return "rpm";
    case SpeedUnit::Hz:
      return "Hz (rev/s)";
  }
  return "?";
}

double to_rad_per_s(double v, SpeedUnit u)
{
  switch (u) {
    case SpeedUnit::RadPerS:
      return v;
    case SpeedUnit::Rpm:
      return v * 2 * kPi / 60;
    case SpeedUnit::Hz:
      return v * 2 * kPi;
  }
  return v;
}

std::vector<double> constant_speed_angle(std::size_t n, double rate, double fr)
{
  std::vector<double> theta(n);
  for (std::size_t i = 0; i < n; ++i) theta[i] = 2 * kPi * fr * static_cast<double>(i) / rate;
  return theta;
}

std::vector<double> angle_from_speed(const std::vector<double> &omega, double rate)
{
  std::vector<double> theta(omega.size(), 0.0);
  const double h = 0.5 / rate;
  for (std::size_t i = 1; i < omega.size(); ++i)
    theta[i] = theta[i - 1] + h * (omega[i - 1] + omega[i]);
  return theta;
}

SpeedSummary speed_summary(const std::vector<double> &theta, double rate, std::size_t blocks)
{
  const std::size_t n = theta.size();
  if (n < 2) throw Error("the shaft angle needs at least 2 samples");
  blocks = std::max<std::size_t>(1, std::min(blocks, (n - 1) / 2));
  SpeedSummary s;
  s.min = INFINITY;
  s.max = -INFINITY;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t i0 = b * (n - 1) / blocks, i1 = (b + 1) * (n - 1) / blocks;
    const double w = (theta[i1] - theta[i0]) * rate / static_cast<double>(i1 - i0);
    s.min = std::min(s.min, w);
    s.max = std::max(s.max, w);
  }
  s.mean = (theta[n - 1] - theta[0]) * rate / static_cast<double>(n - 1);
  s.variation = s.mean != 0 ? (s.max - s.min) / std::fabs(s.mean) : INFINITY;
  return s;
}

double AngleResampled::revolutions() const
{
  return static_cast<double>(x.size()) / samples_per_rev;
}

double default_samples_per_rev(double rate, double mean_omega)
{
  const double per_rev = rate * 2 * kPi / mean_omega;
  return std::max(16.0, 2 * std::ceil(per_rev / 2));
}

double time_at_angle(const std::vector<double> &theta, double rate, double angle)
{
  const auto it = std::lower_bound(theta.begin(), theta.end(), angle);
  if (it == theta.begin()) return 0;
  if (it == theta.end()) return static_cast<double>(theta.size() - 1) / rate;
  const auto j = static_cast<std::size_t>(it - theta.begin()) - 1;
  const double u = (angle - theta[j]) / (theta[j + 1] - theta[j]);
  return (static_cast<double>(j) + u) / rate;
}

AngleResampled resample_by_angle(const std::vector<double> &x, double rate,
                                 const std::vector<double> &theta, double samples_per_rev)
{
  const std::size_t n = x.size();
  if (theta.size() != n)
    throw Error("order tracking: the angle has " + std::to_string(theta.size()) +
                " samples, the signal " + std::to_string(n));
  if (n < 4) throw Error("order tracking needs at least 4 samples");
  if (!(rate > 0)) throw Error("order tracking: the sampling rate must be > 0");
  if (!(samples_per_rev >= 4) || !std::isfinite(samples_per_rev))
    throw SettingError("option {orders.samples_per_rev} expects a number >= 4, got " +
                       format_number(samples_per_rev));
  for (std::size_t j = 0; j + 1 < n; ++j)
    if (!(theta[j + 1] > theta[j]))
      throw Error(
          "order tracking: the shaft angle must increase strictly (the shaft turns one "
          "way, speed > 0); it does not between samples " +
          std::to_string(j + 1) + " and " + std::to_string(j + 2) +
          " (t = " + format_number(static_cast<double>(j) / rate) + " s)");
  static const KaiserTable kaiser;
  const double dtheta = 2 * kPi / samples_per_rev;
  AngleResampled r;
  r.samples_per_rev = samples_per_rev;
  r.flat_order = 0.8 * samples_per_rev / 2;
  const std::size_t m = std::min<std::size_t>(8, (n - 1) / 2);  // span of the speed estimate
  std::size_t j = 0;
  bool started = false;
  for (std::size_t k = 0;; ++k) {
    const double phi = theta[0] + static_cast<double>(k) * dtheta;
    if (phi > theta[n - 1]) break;
    while (j + 2 < n && theta[j + 1] <= phi) ++j;
    const double tau = static_cast<double>(j) + (phi - theta[j]) / (theta[j + 1] - theta[j]);
    // local shaft frequency (rev per input sample) over +-m samples, and the cut-off (cycles per
    // input sample): the angle domain's Nyquist order at that speed, at most the input's Nyquist
    const std::size_t a = j >= m ? j - m : 0, b = std::min(n - 1, j + m + 1);
    const double rev_per_sample = (theta[b] - theta[a]) / static_cast<double>(b - a) / (2 * kPi);
    const double fc = std::min(0.5, 0.5 * samples_per_rev * rev_per_sample);
    const double half = kZeroCrossings / (2 * fc);  // kernel half-length (input samples)
    const bool inside = tau - half >= 0 && tau + half <= static_cast<double>(n - 1);
    if (!inside) {
      if (started) break;
      continue;
    }
    if (!started) {
      started = true;
      r.theta0 = phi;
      r.t0 = tau / rate;
    }
    const auto i0 = static_cast<std::size_t>(std::ceil(tau - half));
    const auto i1 = static_cast<std::size_t>(std::floor(tau + half));
    double sum = 0;
    for (std::size_t i = i0; i <= i1; ++i) {
      const double d = tau - static_cast<double>(i);
      sum += x[i] * 2 * fc * sinc(2 * fc * d) * kaiser(d / half);
    }
    r.x.push_back(sum);
  }
  if (r.x.size() < 16)
    throw Error("order tracking: only " + std::to_string(r.x.size()) +
                " angle samples fit in the record (the kernel needs " +
                format_number(kZeroCrossings) +
                " periods of the cut-off on each side); a longer record or more samples per "
                "revolution needed");
  return r;
}

}  // namespace ohmdem::post
