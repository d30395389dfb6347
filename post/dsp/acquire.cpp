// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/acquire.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "core/error.h"

namespace ohmdem::post {

void validate(const AcquireSettings &s, double fs_in)
{
  if (!(fs_in > 0) || !std::isfinite(fs_in)) throw Error("acquire: the input rate must be > 0 Hz");
  if (!std::isfinite(s.scale) || s.scale == 0)
    throw SettingError("option {acquire.scale} expects a finite, non-zero factor");
  if (!std::isfinite(s.offset))
    throw SettingError("option {acquire.offset} expects a finite number");
  if (s.rate < 0 || !std::isfinite(s.rate))
    throw SettingError("option {acquire.rate} expects a rate > 0 Hz");
  const double fs_out = s.rate > 0 ? s.rate : fs_in;
  if (fs_out > fs_in * (1 + 1e-9))
    throw SettingError("{acquire.rate} " + format_number(fs_out) +
                       " Hz exceeds the input's sampling rate " + format_number(fs_in, 10) +
                       " Hz: an instrument cannot record faster than the signal is known");
  if (s.order < 1 || s.order > kMaxButterworthOrder)
    throw SettingError("option {acquire.order} expects a filter order in 1.." +
                       std::to_string(kMaxButterworthOrder) + ", got " + std::to_string(s.order));
  if (s.lowpass != 0) {
    if (!(s.lowpass > 0) || !std::isfinite(s.lowpass))
      throw SettingError("option {acquire.lowpass} expects a cut-off > 0 Hz");
    if (s.lowpass >= fs_in / 2)
      throw SettingError("{acquire.lowpass} " + format_number(s.lowpass) +
                         " Hz is at or above the input's Nyquist frequency " +
                         format_number(fs_in / 2, 10) + " Hz (the filter runs at the input rate)");
    if (s.lowpass >= fs_out / 2)
      throw SettingError("{acquire.lowpass} " + format_number(s.lowpass) +
                         " Hz is at or above the output Nyquist frequency rate/2 = " +
                         format_number(fs_out / 2, 10) + " Hz: it would not stop aliasing");
  }
  if (s.noise_rms < 0 || !std::isfinite(s.noise_rms))
    throw SettingError("option {acquire.noise_rms} expects a value >= 0");
  if (s.noise_density < 0 || !std::isfinite(s.noise_density))
    throw SettingError("option {acquire.noise_density} expects a value >= 0");
  if (s.noise_rms > 0 && s.noise_density > 0)
    throw SettingError("give the noise once: {acquire.noise_rms} or {acquire.noise_density}");
  if (s.bits != 0) {
    if (s.bits < 1 || s.bits > 32)
      throw SettingError("option {acquire.bits} expects 1..32, got " + std::to_string(s.bits));
    if (!std::isfinite(s.lo) || !std::isfinite(s.hi) || !(s.lo < s.hi))
      throw SettingError("option {acquire.range} expects LO < HI, got " + format_number(s.lo) +
                         " " + format_number(s.hi) + " (an empty ADC range)");
  }
}

std::size_t integer_ratio(double fs_in, double rate)
{
  const double r = fs_in / rate;
  if (!(r < 1e12)) return 0;  // (an absurd ratio: leave it to the sample count check)
  const double k = std::round(r);
  return k >= 1 && std::abs(r - k) <= 1e-6 * r ? static_cast<std::size_t>(k) : 0;
}

std::vector<double> take_every(const std::vector<double> &x, std::size_t k)
{
  std::vector<double> y;
  y.reserve(x.size() / k + 1);
  for (std::size_t i = 0; i < x.size(); i += k) y.push_back(x[i]);
  return y;
}

std::vector<double> interpolate_cubic(const std::vector<double> &x, double step)
{
  if (x.size() < 4) throw Error("cubic interpolation needs at least 4 samples");
  const double last = static_cast<double>(x.size() - 1);
  // positions j*step up to the last sample (the 1e-9 keeps a position that lands on it)
  const auto count = static_cast<std::size_t>(std::floor(last / step + 1e-9)) + 1;
  std::vector<double> y(count);
  for (std::size_t j = 0; j < count; ++j) {
    const double u = std::min(static_cast<double>(j) * step, last);
    // stencil i-1, i, i+1, i+2 around the interval [i, i+1] holding u, kept inside the data
    auto i0 = static_cast<long>(std::floor(u)) - 1;
    i0 = std::max(0L, std::min(i0, static_cast<long>(x.size()) - 4));
    const double d = u - static_cast<double>(i0);  // position within the stencil, in [0, 3]
    const double d0 = d, d1 = d - 1, d2 = d - 2, d3 = d - 3;
    // Lagrange weights for nodes 0, 1, 2, 3
    const double w0 = -d1 * d2 * d3 / 6, w1 = d0 * d2 * d3 / 2, w2 = -d0 * d1 * d3 / 2,
                 w3 = d0 * d1 * d2 / 6;
    const auto i = static_cast<std::size_t>(i0);
    y[j] = w0 * x[i] + w1 * x[i + 1] + w2 * x[i + 2] + w3 * x[i + 3];
  }
  return y;
}

double cubic_interpolation_error(double f, double fs)
{
  return 3.0 / 128 * std::pow(2 * kPi * f / fs, 4);
}

double GaussianNoise::uniform()
{
  // the top 53 bits as k / 2^53, shifted to (0, 1] so that log() stays finite
  return (static_cast<double>(engine_() >> 11) + 1) * 0x1.0p-53;
}

double GaussianNoise::next()
{
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double r = std::sqrt(-2 * std::log(uniform()));
  const double phi = 2 * kPi * uniform();
  spare_ = r * std::sin(phi);
  has_spare_ = true;
  return r * std::cos(phi);
}

std::size_t quantize(std::vector<double> &x, int bits, double lo, double hi)
{
  const double levels = std::ldexp(1.0, bits);
  const double q = (hi - lo) / levels;
  std::size_t clipped = 0;
  for (double &v : x) {
    double k = std::floor((v - lo) / q + 0.5);
    if (k < 0) {
      k = 0;
      ++clipped;
    } else if (k > levels - 1) {
      k = levels - 1;
      ++clipped;
    }
    v = lo + k * q;
  }
  return clipped;
}

Acquisition acquire(const Signal &in, const AcquireSettings &s)
{
  validate(s, in.rate);
  if (in.size() < 4)
    throw Error("acquire needs at least 4 input samples, got " + std::to_string(in.size()));
  for (std::size_t i = 0; i < in.size(); ++i)
    if (!std::isfinite(in.x[i]))
      throw Error("acquire: non-finite value at sample " + std::to_string(i) +
                  " (t = " + format_number(in.time(i), 10) + " s)");
  Acquisition a;
  std::vector<double> y = in.x;
  for (double &v : y) v = s.scale * v + s.offset;

  if (s.lowpass > 0) {
    a.filter = butterworth_lowpass(s.order, s.lowpass, in.rate);
    SosState st = s.steady_start ? sos_steady_state(a.filter, y[0]) : sos_zero_state(a.filter);
    sos_filter(a.filter, y, st);
  }

  double fs_out = in.rate;
  if (s.rate > 0) {
    a.decimation = integer_ratio(in.rate, s.rate);
    if (a.decimation > 0) {
      y = take_every(y, a.decimation);
    } else {
      y = interpolate_cubic(y, in.rate / s.rate);
    }
    // the requested rate, also when it divides the input rate only to 1e-6 (a fitted input
    // rate), so that the time stamps are t0 + i / rate
    fs_out = s.rate;
    if (s.lowpass == 0 && fs_out < in.rate)
      a.warnings.push_back("sampling at " + format_number(fs_out) +
                           " Hz without {acquire.lowpass}: nothing stops aliasing of content above "
                           "rate/2 = " +
                           format_number(fs_out / 2) + " Hz");
  } else {
    a.decimation = 1;
  }
  if (y.size() < 2)
    throw SettingError("{acquire.rate} " + format_number(fs_out) + " Hz leaves " +
                       std::to_string(y.size()) + " sample(s) of the " +
                       format_number(in.duration()) + " s input; at least 2 are needed");

  a.noise_sigma = s.noise_rms > 0 ? s.noise_rms : s.noise_density * std::sqrt(fs_out / 2);
  if (a.noise_sigma > 0) {
    GaussianNoise g(s.seed);
    for (double &v : y) v += a.noise_sigma * g.next();
  }

  if (s.bits > 0) {
    a.q = (s.hi - s.lo) / std::ldexp(1.0, s.bits);
    a.clipped = quantize(y, s.bits, s.lo, s.hi);
    if (a.clipped > 0)
      a.warnings.push_back(
          std::to_string(a.clipped) + " of " + std::to_string(y.size()) + " samples (" +
          format_number(100.0 * static_cast<double>(a.clipped) / static_cast<double>(y.size()), 3) +
          " %) clipped at the ADC range [" + format_number(s.lo) + ", " + format_number(s.hi) +
          "]");
  }

  a.signal.x = std::move(y);
  a.signal.rate = fs_out;
  a.signal.t0 = in.t0;
  a.signal.name = in.name;
  return a;
}

}  // namespace ohmdem::post
