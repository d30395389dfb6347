// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/butterworth.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

namespace {

using cplx = std::complex<double>;

// scipy's numpy.isreal after _cplxreal, whose tolerance is 100 eps relative
bool is_real(cplx z)
{
  return std::abs(z.imag()) <= 100 * std::numeric_limits<double>::epsilon() * std::abs(z);
}

// index of the element closest to the unit circle (zpk2sos's "worst" pole); first on ties
std::size_t worst(const std::vector<cplx> &p, bool real_only)
{
  std::size_t best = p.size();
  double dbest = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (real_only && !is_real(p[i])) continue;
    const double d = std::abs(1 - std::abs(p[i]));
    if (best == p.size() || d < dbest) best = i, dbest = d;
  }
  return best;
}

// index of the zero closest to `to` (our zeros are all real); first on ties
std::size_t nearest(const std::vector<double> &z, cplx to)
{
  std::size_t best = 0;
  for (std::size_t i = 1; i < z.size(); ++i)
    if (std::abs(z[i] - to) < std::abs(z[best] - to)) best = i;
  return best;
}

template <class T>
T take(std::vector<T> &v, std::size_t i)
{
  T x = v[i];
  v.erase(v.begin() + static_cast<long>(i));
  return x;
}

// numpy.poly of up to two real zeros, right-aligned in [b0, b1, b2] as _single_zpksos does
Biquad section(const std::vector<double> &zeros, cplx p1, cplx p2)
{
  Biquad s;
  if (zeros.size() == 2) {
    s.b0 = 1, s.b1 = -(zeros[0] + zeros[1]), s.b2 = zeros[0] * zeros[1];
  } else if (zeros.size() == 1) {
    s.b0 = 0, s.b1 = 1, s.b2 = -zeros[0];
  } else {
    s.b0 = 0, s.b1 = 0, s.b2 = 1;
  }
  s.a1 = -(p1 + p2).real();
  s.a2 = (p1 * p2).real();
  return s;
}

}  // namespace

Sos butterworth_lowpass(int order, double fc, double fs)
{
  if (order < 1 || order > kMaxButterworthOrder)
    throw Error("Butterworth order " + std::to_string(order) + " out of range 1.." +
                std::to_string(kMaxButterworthOrder));
  if (!(fs > 0) || !std::isfinite(fs))
    throw Error("Butterworth design: sampling rate must be > 0 Hz");
  if (!(fc > 0) || !(fc < fs / 2))
    throw Error("Butterworth cut-off " + format_number(fc) +
                " Hz must lie in (0, fs/2 = " + format_number(fs / 2) + " Hz)");
  const int n = order;
  // scipy.signal.iirfilter: frequencies normalised to fs = 2, cut-off prewarped
  const double wn = 2 * fc / fs;
  const double fs2 = 4.0;
  const double warped = 4 * std::tan(kPi * wn / 2);
  // buttap poles -exp(i pi m / 2N), m = -N+1, -N+3, ..., N-1, scaled to the cut-off (lp2lp_zpk)
  // and mapped by the bilinear transform z = (fs2 + s) / (fs2 - s) (bilinear_zpk)
  std::vector<cplx> poles;
  cplx den = 1;
  for (int m = -n + 1; m < n; m += 2) {
    const cplx s = m == 0 ? cplx(-warped, 0) : -std::exp(cplx(0, kPi * m / (2.0 * n))) * warped;
    den *= fs2 - s;
    // zpk2sos keeps one pole of each conjugate pair (the one with positive imaginary part)
    if (m >= 0) poles.push_back((fs2 + s) / (fs2 - s));
  }
  const double k = std::pow(warped, n) * (1.0 / den).real();
  std::vector<double> zeros(static_cast<std::size_t>(n), -1.0);  // the zeros at infinity
  if (n % 2 == 1) {  // 'nearest' pairing pads odd orders with a pole and a zero at the origin
    poles.emplace_back(0.0, 0.0);
    zeros.push_back(0.0);
  }
  // zpk2sos(pairing='nearest'): sections filled from the last, the pole closest to the unit
  // circle first, each with the nearest zeros
  const std::size_t ns = (static_cast<std::size_t>(n) + 1) / 2;
  Sos sos(ns);
  for (std::size_t si = ns; si-- > 0;) {
    const cplx p1 = take(poles, worst(poles, false));
    std::size_t nreal = 0;
    for (cplx p : poles) nreal += is_real(p);
    if (is_real(p1) && nreal == 0) {  // the last real pole: a first-order section
      const double z1 = take(zeros, nearest(zeros, p1));
      sos[si] = section({z1, 0.0}, p1, 0.0);
      continue;
    }
    const cplx p2 = is_real(p1) ? take(poles, worst(poles, true)) : std::conj(p1);
    std::vector<double> zs;
    if (!zeros.empty()) zs.push_back(take(zeros, nearest(zeros, p1)));
    if (!zeros.empty()) zs.push_back(take(zeros, nearest(zeros, p1)));
    sos[si] = section(zs, p1, p2);
  }
  sos[0].b0 *= k;
  sos[0].b1 *= k;
  sos[0].b2 *= k;
  return sos;
}

SosState sos_zero_state(const Sos &sos)
{
  return SosState(sos.size(), {0.0, 0.0});
}

SosState sos_steady_state(const Sos &sos, double x0)
{
  // a section at rest under a constant input u outputs y = H(1) u; the DF2T recursions
  // y = b0 u + z0, z0' = b1 u - a1 y + z1, z1' = b2 u - a2 y then give the fixed point below
  SosState st(sos.size());
  double u = x0;
  for (std::size_t i = 0; i < sos.size(); ++i) {
    const Biquad &s = sos[i];
    const double y = u * (s.b0 + s.b1 + s.b2) / (1 + s.a1 + s.a2);
    st[i][1] = s.b2 * u - s.a2 * y;
    st[i][0] = s.b1 * u - s.a1 * y + st[i][1];
    u = y;
  }
  return st;
}

void sos_filter(const Sos &sos, std::vector<double> &x, SosState &state)
{
  if (state.size() != sos.size()) throw Error("sos_filter: state does not match the sections");
  // the same operations in the same order as scipy's _sosfilt
  for (double &v : x) {
    double xn = v;
    for (std::size_t i = 0; i < sos.size(); ++i) {
      const Biquad &s = sos[i];
      auto &z = state[i];
      const double xc = xn;
      xn = s.b0 * xc + z[0];
      z[0] = s.b1 * xc - s.a1 * xn + z[1];
      z[1] = s.b2 * xc - s.a2 * xn;
    }
    v = xn;
  }
}

std::complex<double> sos_response(const Sos &sos, double f, double fs)
{
  const cplx zi = std::exp(cplx(0, -2 * kPi * f / fs));  // z^-1
  cplx h = 1;
  for (const Biquad &s : sos)
    h *= (s.b0 + zi * (s.b1 + zi * s.b2)) / (1.0 + zi * (s.a1 + zi * s.a2));
  return h;
}

double sos_dc_delay_s(const Sos &sos, double fs)
{
  double samples = 0;
  for (const Biquad &s : sos)
    samples += (s.b1 + 2 * s.b2) / (s.b0 + s.b1 + s.b2) - (s.a1 + 2 * s.a2) / (1 + s.a1 + s.a2);
  return samples / fs;
}

double sos_group_delay_s(const Sos &sos, double f, double fs)
{
  const std::complex<double> z1 = std::polar(1.0, -2 * kPi * f / fs), z2 = z1 * z1;  // z^-1, z^-2
  // -d phase / d omega of c0 + c1 z^-1 + c2 z^-2, in samples
  const auto delay = [&](double c0, double c1, double c2) {
    return ((c1 * z1 + 2 * c2 * z2) / (c0 + c1 * z1 + c2 * z2)).real();
  };
  double samples = 0;
  for (const Biquad &s : sos) samples += delay(s.b0, s.b1, s.b2) - delay(1, s.a1, s.a2);
  return samples / fs;
}

double butterworth_gain(int order, double fc, double fs, double f)
{
  const double r = std::tan(kPi * f / fs) / std::tan(kPi * fc / fs);
  return 1 / std::sqrt(1 + std::pow(r * r, order));
}

}  // namespace ohmdem::post
