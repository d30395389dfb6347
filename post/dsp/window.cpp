// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/window.h"

#include <cmath>
#include <complex>

#include "core/constants.h"
#include "core/error.h"

namespace ohmdem::post {

namespace {

// cosine-sum coefficients a_0..a_4 (scipy.signal.windows; flattop is the ISO 18431-2 / MATLAB one)
struct Coeffs {
  double a[5];
  int m;
};

Coeffs coeffs(WindowKind w)
{
  switch (w) {
    case WindowKind::Rectangular:
      return {{1, 0, 0, 0, 0}, 1};
    case WindowKind::Hann:
      return {{0.5, 0.5, 0, 0, 0}, 2};
    case WindowKind::Hamming:
      return {{0.54, 0.46, 0, 0, 0}, 2};
    case WindowKind::Blackman:
      return {{0.42, 0.50, 0.08, 0, 0}, 3};
    case WindowKind::BlackmanHarris:
      return {{0.35875, 0.48829, 0.14128, 0.01168, 0}, 4};
    case WindowKind::Flattop:
      return {{0.21557895, 0.41663158, 0.277263158, 0.083578947, 0.006947368}, 5};
  }
  return {{1, 0, 0, 0, 0}, 1};
}

// sum_{j=0}^{n-1} e^{-2 pi i j v}, v in cycles per sample (geometric series)
std::complex<double> dirichlet(double v, std::size_t n)
{
  const double s = std::sin(kPi * v);
  const double dn = static_cast<double>(n);
  const std::complex<double> phase = std::polar(1.0, -kPi * v * (dn - 1));
  // at integer v every term is 1
  if (std::fabs(s) < 1e-14) return dn;
  return phase * (std::sin(kPi * v * dn) / s);
}

}  // namespace

WindowKind parse_window(const std::string &name)
{
  if (name == "rect" || name == "rectangular" || name == "boxcar" || name == "none")
    return WindowKind::Rectangular;
  if (name == "hann" || name == "hanning") return WindowKind::Hann;
  if (name == "hamming") return WindowKind::Hamming;
  if (name == "blackman") return WindowKind::Blackman;
  if (name == "blackmanharris") return WindowKind::BlackmanHarris;
  if (name == "flattop") return WindowKind::Flattop;
  throw SettingError(std::string("option {spectrum.window} expects ") + window_names() + ", got '" +
                     name + "'");
}

const char *window_names()
{
  return "rect|hann|hamming|blackman|blackmanharris|flattop";
}

const char *window_name(WindowKind w)
{
  switch (w) {
    case WindowKind::Rectangular:
      return "rect";
    case WindowKind::Hann:
      return "hann";
    case WindowKind::Hamming:
      return "hamming";
    case WindowKind::Blackman:
      return "blackman";
    case WindowKind::BlackmanHarris:
      return "blackmanharris";
    case WindowKind::Flattop:
      return "flattop";
  }
  return "?";
}

std::vector<double> make_window(WindowKind w, std::size_t n)
{
  const Coeffs c = coeffs(w);
  std::vector<double> v(n);
  for (std::size_t j = 0; j < n; ++j) {
    // the m = 0 term's cos(0) is 1: not a libm call per sample (a record of 1e6 samples)
    double s = c.a[0], sign = -1;
    for (int m = 1; m < c.m; ++m, sign = -sign)
      s += sign * c.a[m] * std::cos(2 * kPi * m * static_cast<double>(j) / static_cast<double>(n));
    v[j] = s;
  }
  return v;
}

WindowKernel::WindowKernel(WindowKind w, std::size_t n, std::size_t nfft)
    : w_(w), n_(n), nfft_(nfft)
{
  const Coeffs c = coeffs(w);
  std::complex<double> sum0 = c.a[0] * dirichlet(0, n);
  double sign = -1;
  for (int m = 1; m < c.m; ++m, sign = -sign) {
    const double q = static_cast<double>(m) / static_cast<double>(n);
    sum0 += sign * c.a[m] / 2 * (dirichlet(-q, n) + dirichlet(q, n));
  }
  norm0_ = std::abs(sum0);
}

double WindowKernel::operator()(double u) const
{
  const Coeffs c = coeffs(w_);
  const double v = u / static_cast<double>(nfft_);  // cycles per sample
  std::complex<double> sum = c.a[0] * dirichlet(v, n_);
  double sign = -1;
  for (int m = 1; m < c.m; ++m, sign = -sign) {
    const double q = static_cast<double>(m) / static_cast<double>(n_);
    sum += sign * c.a[m] / 2 * (dirichlet(v - q, n_) + dirichlet(v + q, n_));
  }
  return std::abs(sum) / norm0_;
}

double window_kernel(WindowKind w, std::size_t n, std::size_t nfft, double u)
{
  return WindowKernel(w, n, nfft)(u);
}

double main_lobe_half_width(WindowKind w)
{
  return coeffs(w).m;
}

}  // namespace ohmdem::post
