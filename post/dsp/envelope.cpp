// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"
#include "dsp/fft.h"

namespace ohmdem::post {

namespace {

void check_band(Band &band, double rate)
{
  const double nyq = rate / 2;
  if (band.hi <= 0) band.hi = nyq;
  if (band.lo < 0 || band.hi > nyq * (1 + 1e-12) || !(band.hi > band.lo))
    throw Error("band [" + format_number(band.lo) + ", " + format_number(band.hi) +
                "] Hz must satisfy 0 <= f1 < f2 <= fs/2 = " + format_number(nyq) + " Hz");
}

}  // namespace

std::vector<double> envelope(const std::vector<double> &x, double rate, Band band)
{
  const std::size_t n = x.size();
  if (n < 4) throw Error("an envelope needs at least 4 samples, got " + std::to_string(n));
  check_band(band, rate);
  // work arrays of this call only: nothing of a long record's size stays allocated after it
  std::vector<Complex> X, Y;
  rfft(x.data(), n, X);
  const double df = rate / static_cast<double>(n);
  const std::size_t nb = X.size();
  const bool has_nyquist = n % 2 == 0;
  // analytic signal z = x_band + i H[x_band]: both parts through c2r transforms of half spectra
  // (cheaper than one c2c of length n); for the whole band the real part is x itself
  std::size_t kept = 0;
  std::size_t k_lo = nb, k_hi = 0;
  for (std::size_t k = 0; k < nb; ++k) {
    const double f = static_cast<double>(k) * df;
    if (f < band.lo || f > band.hi) continue;
    k_lo = std::min(k_lo, k);
    k_hi = std::max(k_hi, k);
    ++kept;
  }
  if (kept == 0)
    throw Error("band [" + format_number(band.lo) + ", " + format_number(band.hi) +
                "] Hz holds no frequency bin (resolution " + format_number(df) + " Hz)");
  const bool whole = k_lo == 0 && k_hi == nb - 1;
  std::vector<double> re;
  const double inv = 1.0 / static_cast<double>(n);
  if (!whole) {
    Y.assign(nb, Complex(0, 0));
    for (std::size_t k = k_lo; k <= k_hi; ++k) Y[k] = X[k];
    re.resize(n);
    irfft(Y, n, re.data());
    for (double &v : re) v *= inv;
  }
  // Hilbert transform: -i sign(f) X, zero at DC and Nyquist (the analytic signal keeps those
  // once, in its real part, as scipy.signal.hilbert)
  Y.assign(nb, Complex(0, 0));
  for (std::size_t k = std::max<std::size_t>(k_lo, 1); k <= k_hi; ++k)
    if (!(has_nyquist && k == nb - 1)) Y[k] = Complex(X[k].imag(), -X[k].real());
  std::vector<Complex>().swap(X);  // freed before env is allocated: lower peak memory
  std::vector<double> env(n);
  irfft(Y, n, env.data());
  const std::vector<double> &r = whole ? x : re;
  for (std::size_t j = 0; j < n; ++j) env[j] = std::hypot(r[j], env[j] * inv);
  return env;
}

namespace {

// z with P(N(0,1) > z) = p, by Newton on erfc (p in (0, 1)).
double normal_upper_quantile(double p)
{
  double z = 0;
  for (int it = 0; it < 100; ++it) {
    const double f = 0.5 * std::erfc(z / std::sqrt(2.0)) - p;
    const double d = -std::exp(-0.5 * z * z) / std::sqrt(2 * kPi);
    const double step = f / d;
    z -= std::max(-2.0, std::min(2.0, step));
    if (std::fabs(step) < 1e-14 * std::max(1.0, std::fabs(z))) break;
  }
  return z;
}

}  // namespace

double sk_threshold(std::size_t m, double alpha)
{
  if (m < 2) throw Error("spectral kurtosis threshold: a band needs at least 2 samples");
  if (!(alpha > 0 && alpha < 1))
    throw Error("spectral kurtosis threshold: alpha must be in (0, 1)");
  const double M = static_cast<double>(m);
  // raw moments of Greenwood's statistic G = sum D_i^2 (D uniform spacings): sums over index
  // patterns of Dirichlet moments E prod D_i^(2 a_i) = Gamma(M) prod (2 a_i)! / Gamma(M + 2 sum a)
  const double r4 = (M + 1) * (M + 2) * (M + 3), r6 = r4 * (M + 4) * (M + 5),
               r8 = r6 * (M + 6) * (M + 7), q = M - 1;
  const double g1 = 2 / (M + 1);
  const double g2 = (24 + 4 * q) / r4;
  const double g3 = (720 + 144 * q + 8 * q * (q - 1)) / r6;
  const double g4 =
      (40320 + 4 * q * 1440 + 3 * q * 576 + 6 * q * (q - 1) * 96 + q * (q - 1) * (q - 2) * 16) / r8;
  const double var = g2 - g1 * g1;
  const double c3 = g3 - 3 * g1 * g2 + 2 * g1 * g1 * g1;
  const double c4 = g4 - 4 * g1 * g3 + 6 * g1 * g1 * g2 - 3 * g1 * g1 * g1 * g1;
  const double mean = M * g1 - 2, sd = M * std::sqrt(var);
  const double skew = c3 / std::pow(var, 1.5), exkurt = c4 / (var * var) - 3;
  const double z = normal_upper_quantile(alpha);
  // Wilson-Hilferty quantile of a Pearson type III law with this skewness: accurate to
  // alpha ~ 1e-3, too low (liberal) further out; the Cornish-Fisher expansion with the fourth
  // moment is high (conservative) there. The larger of the two (numpy Monte Carlo, M = 16 ..
  // 1024, alpha = 0.05 .. 2e-5): rate / alpha between 0.2 and 1.2.
  const double wh = (2 / skew) * (std::pow(1 + skew * z / 6 - skew * skew / 36, 3) - 1);
  const double cf = z + (z * z - 1) * skew / 6 + (z * z * z - 3 * z) * exkurt / 24 -
                    (2 * z * z * z - 5 * z) * skew * skew / 36;
  return mean + sd * std::max(wh, cf);
}

std::vector<double> end_jump_removed(const std::vector<double> &x)
{
  const std::size_t n = x.size(), L = std::max<std::size_t>(1, n / 32);
  double m0 = 0, m1 = 0;
  for (std::size_t i = 0; i < L; ++i) {
    m0 += x[i] / static_cast<double>(L);
    m1 += x[n - L + i] / static_cast<double>(L);
  }
  std::vector<double> y = x;
  const double slope = (m1 - m0) / static_cast<double>(n - L),
               mid = (static_cast<double>(L) - 1) / 2;
  for (std::size_t i = 0; i < n; ++i) y[i] -= m0 + slope * (static_cast<double>(i) - mid);
  return y;
}

namespace {

Kurtogram kurtogram_of(const std::vector<double> &x, double rate, int max_level,
                       double min_bandwidth, double fmin, double alpha,
                       std::vector<Complex> *best_envelope)
{
  const std::size_t n = x.size();
  if (n < 64) throw Error("a kurtogram needs at least 64 samples, got " + std::to_string(n));
  std::vector<double> y = end_jump_removed(x);
  std::vector<Complex> X;
  rfft(y.data(), n, X);
  std::vector<double>().swap(y);
  const double df = rate / static_cast<double>(n), nyq = rate / 2;

  std::vector<int> counts;
  for (int l = 0; l <= max_level; ++l) {
    counts.push_back(1 << l);
    if (l >= 1 && l < max_level) counts.push_back(3 << (l - 1));  // 3, 6, 12, ...
  }
  counts.erase(std::remove_if(counts.begin(), counts.end(),
                              [&](int c) { return c > 1 && nyq / c < min_bandwidth; }),
               counts.end());
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());

  Kurtogram kg;
  kg.best.kurtosis = -std::numeric_limits<double>::infinity();
  std::vector<Complex> c;
  for (int nbands : counts) {
    const double bw = nyq / nbands;
    for (int i = 0; i < nbands; ++i) {
      const double lo = i * bw, hi = (i + 1) * bw;
      if (hi <= fmin) continue;
      const auto k1 = static_cast<std::size_t>(std::max(1.0, std::ceil(lo / df)));
      const auto k2 = std::min(X.size() - 1, static_cast<std::size_t>(std::floor(hi / df)));
      if (k2 < k1 + 7) continue;
      c.assign(X.begin() + static_cast<long>(k1), X.begin() + static_cast<long>(k2) + 1);
      cfft(c, +1);
      const std::size_t guard = end_guard(c.size());
      double s2 = 0, s4 = 0;
      for (std::size_t j = guard; j + guard < c.size(); ++j) {
        const double p = std::norm(c[j]);
        s2 += p;
        s4 += p * p;
      }
      const std::size_t kept = c.size() - 2 * guard;
      const double m = static_cast<double>(kept);
      KurtogramCell cell{nbands, lo, hi, s2 > 0 ? (s4 / m) / ((s2 / m) * (s2 / m)) - 2 : 0, kept};
      kg.cells.push_back(cell);
      if (cell.kurtosis > kg.best.kurtosis) {
        kg.best = cell;
        if (best_envelope) c.swap(*best_envelope);
      }
    }
  }
  if (kg.cells.empty()) throw Error("kurtogram: no band wide enough (signal too short?)");
  kg.alpha = alpha;
  kg.threshold = sk_threshold(kg.best.samples, alpha / static_cast<double>(kg.cells.size()));
  kg.significant = kg.best.kurtosis > kg.threshold;
  return kg;
}

}  // namespace

Kurtogram kurtogram(const std::vector<double> &x, double rate, int max_level, double min_bandwidth,
                    double fmin, double alpha)
{
  return kurtogram_of(x, rate, max_level, min_bandwidth, fmin, alpha, nullptr);
}

Kurtogram kurtogram(const std::vector<double> &x, double rate, int max_level, double min_bandwidth,
                    std::vector<Complex> &best_envelope)
{
  return kurtogram_of(x, rate, max_level, min_bandwidth, 0, 0.01, &best_envelope);
}

}  // namespace ohmdem::post
