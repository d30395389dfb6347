// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/detect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.h"
#include "core/sampled_signal.h"
#include "dsp/detect_laws.h"
#include "dsp/fft.h"
#include "dsp/spectrum.h"
#include "dsp/stats.h"

namespace ohmdem::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t next_pow2(std::size_t n)
{
  std::size_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

// Effective count of the m complex samples c of a band for its spectral kurtosis: m / S with
// S = sum over the circular lags of rho_l^2, rho the autocorrelation of the squared envelope
// |c|^2. For circular Gaussian c, rho_l = |rho_c(l)|^2, so S = sum |rho_c|^4 (the count of the
// sample kurtosis); a periodic modulation of the band (a shaft-synchronous one in a healthy
// machine) raises S and is counted as dependence, not as evidence. Each estimated rho_l^2
// carries about 1/m of sampling noise, removed (S >= 1).
double band_effective_samples(const std::vector<Complex> &c)
{
  const std::size_t m = c.size();
  std::vector<Complex> p(m);
  double mean = 0;
  for (std::size_t i = 0; i < m; ++i) mean += std::norm(c[i]) / static_cast<double>(m);
  for (std::size_t i = 0; i < m; ++i) p[i] = std::norm(c[i]) - mean;
  cfft(p, -1);
  for (Complex &v : p) v = std::norm(v);
  cfft(p, +1);  // circular autocovariance x m
  const double r0 = p[0].real();
  if (!(r0 > 0)) return 0;
  const double dm = static_cast<double>(m);
  double s = 1;
  for (std::size_t l = 1; l < m; ++l) s += std::pow(p[l].real() / r0, 2) - 1 / dm;
  return dm / std::max(s, 1.0);
}

}  // namespace

double kurtosis_effective_samples(const std::vector<double> &x)
{
  const std::size_t n = x.size();
  const std::size_t nfft = next_pow2(2 * n);
  std::vector<double> padded(nfft, 0.0);
  std::copy(x.begin(), x.end(), padded.begin());
  std::vector<Complex> X;
  rfft(padded.data(), nfft, X);
  for (Complex &v : X) v = std::norm(v);
  std::vector<double> r(nfft);
  irfft(X, nfft, r.data());  // r[k] = nfft x sum_t x_t x_{t+k}: the biased autocovariance
  if (!(r[0] > 0)) return kNaN;
  double s = 1;
  for (std::size_t k = 1; k < n; ++k) s += 2 * std::pow(r[k] / r[0], 4);
  return static_cast<double>(n) / s;
}

namespace {

// white_floor_ratio with the record's standard deviation sd given
double white_floor_ratio(const std::vector<double> &x, double sd)
{
  // second differences of disjoint triples, (x_3i - 2 x_3i+1 + x_3i+2)/sqrt(6): N(0, sigma^2)
  // for white noise of sigma, ~(2 pi f/fs)^2 for a smooth component of frequency f
  const std::size_t h = x.size() / 3;
  if (h == 0) return 0;
  std::vector<double> d(h);
  for (std::size_t i = 0; i < h; ++i)
    d[i] = std::fabs(x[3 * i] - 2 * x[3 * i + 1] + x[3 * i + 2]) / std::sqrt(6.0);
  std::nth_element(d.begin(), d.begin() + static_cast<long>(h / 2), d.end());
  const double sigma_w = d[h / 2] / 0.6744897501960817;  // Phi^-1(3/4): MAD of N(0, 1)
  return sd > 0 ? sigma_w / sd : 0;
}

}  // namespace

double white_floor_ratio(const std::vector<double> &x)
{
  return white_floor_ratio(x, indicators(x).std);
}

namespace {

// Spectral kurtosis of a band and its effective number of complex samples, computed as the
// kurtogram does (ideal FFT band of the mean-removed record, complex envelope at baseband).
struct BandKurtosis {
  double sk = kNaN, m = 0, m_eff = 0;
};

// The band's complex envelope at baseband, ends included (empty below 8 bins).
std::vector<Complex> band_envelope(const std::vector<double> &x, double rate, Band band)
{
  // the end jump treated as the kurtogram treats it (envelope.h): the band the kurtogram
  // chose is judged on the statistic it was chosen by
  const std::size_t n = x.size();
  const std::vector<double> y = end_jump_removed(x);
  std::vector<Complex> X;
  rfft(y.data(), n, X);
  const double df = rate / static_cast<double>(n);
  const double hi = band.hi > 0 ? band.hi : rate / 2;
  const auto k1 = static_cast<std::size_t>(std::max(1.0, std::ceil(band.lo / df)));
  const auto k2 = std::min(X.size() - 1, static_cast<std::size_t>(std::floor(hi / df)));
  if (k2 < k1 + 7) return {};
  std::vector<Complex> full(X.begin() + static_cast<long>(k1),
                            X.begin() + static_cast<long>(k2) + 1);
  cfft(full, +1);
  return full;
}

BandKurtosis band_kurtosis(const std::vector<double> &x, double rate, Band band,
                           const std::vector<Complex> *given)
{
  BandKurtosis b;
  const std::vector<Complex> made = given ? std::vector<Complex>() : band_envelope(x, rate, band);
  const std::vector<Complex> &full = given ? *given : made;
  if (full.empty()) return b;
  const std::size_t guard = end_guard(full.size());
  const std::vector<Complex> c(full.begin() + static_cast<long>(guard),
                               full.end() - static_cast<long>(guard));
  double s2 = 0, s4 = 0;
  for (const Complex &v : c) {
    const double p = std::norm(v);
    s2 += p;
    s4 += p * p;
  }
  b.m = static_cast<double>(c.size());
  if (!(s2 > 0)) return b;
  b.sk = (s4 / b.m) / ((s2 / b.m) * (s2 / b.m)) - 2;
  b.m_eff = band_effective_samples(c);
  return b;
}

// ind: the indicators of x (detect's, computed once)
DetectionTest gaussian_kurtosis(const std::vector<double> &x, const Indicators &ind, double p)
{
  DetectionTest t;
  t.name = "kurtosis";
  t.reference = "gaussian";
  t.value = ind.kurtosis;
  t.samples = kurtosis_effective_samples(x);
  // scipy.stats.kurtosistest asks for n >= 20 (the Anscombe-Glynn approximation below that)
  if (!(t.samples >= 20)) {
    t.applicable = false;
    t.threshold = t.p_value = kNaN;
    t.note = "fewer than 20 independent samples";
    return t;
  }
  t.threshold = kurtosis_threshold(t.samples, p);
  t.p_value = kurtosis_sf(t.value, t.samples);
  t.fired = t.value > t.threshold;
  return t;
}

DetectionTest gaussian_crest(const std::vector<double> &x, const Indicators &ind, double p)
{
  DetectionTest t;
  t.name = "crest";
  t.reference = "gaussian";
  t.value = ind.peak / ind.std;  // x is mean-removed: peak |x - mean| / sigma
  t.samples = static_cast<double>(x.size());
  t.threshold = crest_threshold(t.samples, p);
  t.p_value = crest_sf(t.value, t.samples);
  t.fired = t.value > t.threshold;
  return t;
}

DetectionTest gaussian_band(const std::vector<double> &x, double rate, const DetectOptions &opt)
{
  DetectionTest t;
  t.name = "band_sk";
  t.reference = "gaussian";
  const BandKurtosis b = band_kurtosis(x, rate, opt.band, opt.band_envelope);
  t.value = b.sk;
  t.samples = b.m_eff;
  if (!(b.m_eff >= 8) || !std::isfinite(b.sk)) {
    t.applicable = false;
    t.threshold = t.p_value = kNaN;
    t.note = "band holds fewer than 8 independent complex samples";
    return t;
  }
  // the band was the largest spectral kurtosis among bands_searched: Bonferroni
  const double per_band =
      opt.false_alarm / static_cast<double>(std::max<std::size_t>(1, opt.bands_searched));
  t.threshold = spectral_kurtosis_threshold(b.m_eff, per_band);
  t.p_value = std::min(1.0, spectral_kurtosis_sf(b.sk, b.m_eff) *
                                static_cast<double>(std::max<std::size_t>(1, opt.bands_searched)));
  t.fired = t.value > t.threshold;
  if (opt.bands_searched > 1)
    t.note = "threshold at p/" + std::to_string(opt.bands_searched) + " (kurtogram bands)";
  return t;
}

// ---- baseline: window statistics (logarithms: positive, skewed quantities)
struct WindowStats {
  double log_rms, log_kurtosis, log_crest, log_band;
};

WindowStats window_stats(const double *w, std::size_t n, double rate, Band band)
{
  std::vector<double> x(w, w + n);
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
  for (double &v : x) v -= mean;
  const Indicators ind = indicators(x);
  if (!(ind.std > 0))
    throw SettingError("a window of the record or of {detect.baseline} is constant");
  // band mean square from the Hann-windowed power spectrum (it sums to the mean square)
  SpectrumOptions o;
  o.window = WindowKind::Hann;
  o.detrend = Detrend::Mean;
  o.scaling = Scaling::Power;
  const Spectrum s = spectrum(x, rate, o);
  const double hi = band.hi > 0 ? band.hi : rate / 2;
  double e = 0;
  for (std::size_t k = 1; k < s.bins(); ++k) {
    const double f = static_cast<double>(k) * s.df;
    if (f >= band.lo && f <= hi) e += s.value[k];
  }
  return {std::log(ind.std), std::log(ind.kurtosis), std::log(ind.peak / ind.std),
          std::log(std::max(e, 1e-300))};
}

std::vector<DetectionTest> baseline_tests(const std::vector<double> &x, double rate,
                                          const std::vector<double> &base, const DetectOptions &opt)
{
  const std::size_t W0 = std::max<std::size_t>(opt.baseline_windows, 3);
  const std::size_t len = std::min(base.size() / W0, x.size());
  const struct {
    const char *name;
    double WindowStats::*field;
  } stats[] = {{"baseline_rms", &WindowStats::log_rms},
               {"baseline_kurtosis", &WindowStats::log_kurtosis},
               {"baseline_crest", &WindowStats::log_crest},
               {"baseline_band_energy", &WindowStats::log_band}};
  std::vector<DetectionTest> out;
  if (len < 256) {
    // Too short to estimate the healthy scatter (a slow instrument over a short record): the
    // tests are not applicable, as the Gaussian ones are without a noise floor.
    for (const auto &st : stats) {
      DetectionTest t;
      t.name = st.name;
      t.reference = "baseline";
      t.value = t.threshold = t.p_value = std::numeric_limits<double>::quiet_NaN();
      t.applicable = false;
      t.note = "record or baseline too short: " + std::to_string(base.size()) + " and " +
               std::to_string(x.size()) + " samples give windows of " + std::to_string(len) +
               " < 256 samples (" + std::to_string(W0) + " baseline windows)";
      out.push_back(t);
    }
    return out;
  }
  const std::size_t W = base.size() / len, M = x.size() / len;
  std::vector<WindowStats> b, r;
  for (std::size_t i = 0; i < W; ++i)
    b.push_back(window_stats(base.data() + i * len, len, rate, opt.band));
  for (std::size_t i = 0; i < M; ++i)
    r.push_back(window_stats(x.data() + i * len, len, rate, opt.band));
  // prediction bound for the mean of M new windows from W healthy ones (normal law, unknown
  // variance): mean_b + t_{W-1, 1-p} sd_b sqrt(1/W + 1/M)
  const double tq = student_t_isf(opt.false_alarm, static_cast<double>(W - 1));
  const double spread = std::sqrt(1.0 / static_cast<double>(W) + 1.0 / static_cast<double>(M));
  for (const auto &st : stats) {
    double mb = 0, mr = 0;
    for (const auto &w : b) mb += w.*st.field / static_cast<double>(W);
    for (const auto &w : r) mr += w.*st.field / static_cast<double>(M);
    double var = 0;
    for (const auto &w : b) var += (w.*st.field - mb) * (w.*st.field - mb);
    // windows of a strictly periodic record can agree to the last bits: the scatter is floored
    // at the resolution of a double statistic
    const double sd = std::max(std::sqrt(var / static_cast<double>(W - 1)),
                               64 * std::numeric_limits<double>::epsilon() * (1 + std::fabs(mb)));
    DetectionTest t;
    t.name = st.name;
    t.reference = "baseline";
    t.value = std::exp(mr);
    t.threshold = std::exp(mb + tq * sd * spread);
    t.p_value = student_t_sf((mr - mb) / (sd * spread), static_cast<double>(W - 1));
    t.samples = static_cast<double>(M);
    t.fired = mr > mb + tq * sd * spread;
    t.note = std::to_string(M) + " window(s) of " + std::to_string(len) + " samples against " +
             std::to_string(W) + " baseline windows";
    out.push_back(t);
  }
  return out;
}

}  // namespace

Detection detect(const std::vector<double> &x, double rate, const DetectOptions &opt,
                 const std::vector<double> *baseline)
{
  check_probability(opt.false_alarm, "{detect.false_alarm}");
  if (x.size() < 256) throw Error("detection needs at least 256 samples");
  Detection d;
  const Indicators ind = indicators(x);  // the three statistics below read them
  d.white_floor = white_floor_ratio(x, ind.std);
  d.gaussian_applicable = d.white_floor >= kMinWhiteFloor;
  d.gaussian_note = d.gaussian_applicable
                        ? "white noise floor " + format_number(d.white_floor, 3) + " of the spread"
                        : "no noise floor (white floor " + format_number(d.white_floor, 3) +
                              " of the spread < " + format_number(kMinWhiteFloor) +
                              "): a deterministic record, judged only against {detect.baseline}";
  std::vector<DetectionTest> g = {gaussian_kurtosis(x, ind, opt.false_alarm),
                                  gaussian_crest(x, ind, opt.false_alarm),
                                  gaussian_band(x, rate, opt)};
  for (auto &t : g) {
    if (!d.gaussian_applicable && t.applicable) {
      t.applicable = false;
      t.note = "no noise floor";
    }
    // A healthy machine need not be Gaussian (a loaded bearing's vibration has its own
    // impulsive ball passes): with a baseline, the healthy record is the reference and the
    // Gaussian statistics are shown for information only.
    if (baseline && t.applicable) {
      t.applicable = false;
      t.note = "for information: with {detect.baseline} the healthy record is the reference";
    }
    if (!t.applicable) t.fired = false;
    d.tests.push_back(t);
  }
  if (baseline)
    for (auto &t : baseline_tests(x, rate, *baseline, opt)) d.tests.push_back(t);
  for (const auto &t : d.tests) {
    if (!t.applicable) continue;
    ++d.tests_applied;
    d.fired = d.fired || t.fired;
  }
  d.false_alarm_bound = std::min(1.0, static_cast<double>(d.tests_applied) * opt.false_alarm);
  return d;
}

}  // namespace ohmdem::post
