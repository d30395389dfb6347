// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/spectrum.h"

#include <cmath>

#include "core/error.h"
#include "core/index_line_fit.h"
#include "dsp/fft.h"

namespace ohmdem::post {

Detrend parse_detrend(const std::string &name)
{
  if (name == "none") return Detrend::None;
  if (name == "mean" || name == "constant") return Detrend::Mean;
  if (name == "linear") return Detrend::Linear;
  throw SettingError("option {spectrum.detrend} expects none|mean|linear, got '" + name + "'");
}

const char *detrend_name(Detrend d)
{
  return d == Detrend::None ? "none" : d == Detrend::Mean ? "mean" : "linear";
}

Scaling parse_scaling(const std::string &name)
{
  if (name == "amplitude") return Scaling::Amplitude;
  if (name == "power") return Scaling::Power;
  if (name == "psd") return Scaling::Psd;
  throw SettingError("option {spectrum.scale} expects amplitude|power|psd, got '" + name + "'");
}

const char *scaling_name(Scaling s)
{
  return s == Scaling::Amplitude ? "amplitude" : s == Scaling::Power ? "power" : "psd";
}

const char *scaling_unit(Scaling s)
{
  return s == Scaling::Amplitude ? "" : s == Scaling::Power ? "^2" : "^2/Hz";
}

void detrend(double *x, std::size_t n, Detrend d)
{
  if (d == Detrend::None || n == 0) return;
  IndexLineFit line = fit_line_to_index(x, n);
  if (d == Detrend::Mean) line.slope = 0;
  for (std::size_t i = 0; i < n; ++i) x[i] -= line.at(i);
}

Spectrum spectrum(const std::vector<double> &x, double rate, const SpectrumOptions &opt)
{
  const std::size_t n = x.size();
  if (n < 4) throw Error("a spectrum needs at least 4 samples, got " + std::to_string(n));
  if (!(rate > 0)) throw Error("sampling rate must be > 0");
  const std::size_t seg = opt.segment ? opt.segment : n;
  if (seg > n)
    throw SettingError("option {spectrum.segment} (" + std::to_string(seg) +
                       " samples) exceeds the signal (" + std::to_string(n) + " samples)");
  if (seg < 4) throw SettingError("option {spectrum.segment} must be at least 4 samples");
  if (!(opt.overlap >= 0 && opt.overlap < 1))
    throw SettingError("option {spectrum.overlap} expects a fraction in [0, 1)");
  if (opt.pad < 1) throw SettingError("option {spectrum.pad} expects an integer >= 1");
  const std::size_t nfft = opt.nfft ? opt.nfft : seg * opt.pad;
  if (nfft < seg)
    throw SettingError("option {spectrum.nfft} (" + std::to_string(nfft) +
                       ") must be at least the segment length (" + std::to_string(seg) + ")");
  auto step = static_cast<std::size_t>(std::floor(static_cast<double>(seg) * (1 - opt.overlap)));
  if (step < 1) step = 1;

  // the window of the last call is kept (same size and kind: no recomputation)
  static std::vector<double> w;
  static WindowKind w_kind = WindowKind::Rectangular;
  if (w.size() != seg || w_kind != opt.window) {
    w = make_window(opt.window, seg);
    w_kind = opt.window;
  }
  double sw = 0, sw2 = 0;
  for (double v : w) {
    sw += v;
    sw2 += v * v;
  }
  Spectrum s;
  s.scaling = opt.scaling;
  s.window = opt.window;
  s.segment = seg;
  s.nfft = nfft;
  s.rate = rate;
  s.df = rate / static_cast<double>(nfft);
  s.enbw_hz = rate * sw2 / (sw * sw);
  const std::size_t nb = nfft / 2 + 1;
  // work arrays of this call only: nothing of a long record's size stays allocated after it
  std::vector<double> buf(nfft);
  std::vector<Complex> X;
  std::vector<double> &acc = s.value;  // sum of |X|^2, scaled in place below
  acc.assign(nb, 0.0);
  for (std::size_t start = 0; start + seg <= n; start += step) {
    const double *xs = x.data() + start;
    if (opt.detrend == Detrend::Mean) {
      double mean = 0;
      for (std::size_t j = 0; j < seg; ++j) mean += xs[j];
      mean /= static_cast<double>(seg);
      for (std::size_t j = 0; j < seg; ++j) buf[j] = (xs[j] - mean) * w[j];
    } else {
      std::copy(xs, xs + seg, buf.begin());
      detrend(buf.data(), seg, opt.detrend);
      for (std::size_t j = 0; j < seg; ++j) buf[j] *= w[j];
    }
    std::fill(buf.begin() + static_cast<long>(seg), buf.end(), 0.0);
    rfft(buf.data(), nfft, X);
    for (std::size_t k = 0; k < nb; ++k) acc[k] += std::norm(X[k]);
    ++s.segments;
  }
  // one-sided: every bin except DC and (even nfft) Nyquist carries its negative twin
  const double inv = 1.0 / static_cast<double>(s.segments);
  for (std::size_t k = 0; k < nb; ++k) {
    const bool single = k == 0 || (nfft % 2 == 0 && k == nfft / 2);
    const double p = acc[k] * inv * (single ? 1.0 : 2.0);  // sum of |X|^2 both sides
    switch (opt.scaling) {
      case Scaling::Power:
        s.value[k] = p / (sw * sw);
        break;
      case Scaling::Psd:
        s.value[k] = p / (rate * sw2);
        break;
      // a sine of amplitude A gives |X| = A sw / 2 on each side: A = 2 |X| / sw
      case Scaling::Amplitude:
        s.value[k] = std::sqrt(p * (single ? 1.0 : 2.0)) / sw;
        break;
    }
  }
  return s;
}

}  // namespace ohmdem::post
