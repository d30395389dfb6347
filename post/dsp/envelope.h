// SPDX-License-Identifier: GPL-2.0-or-later
// Envelope analysis: ideal band-pass in the frequency domain and Hilbert transform through
// FFTW (|analytic signal|), and the fast spectral-kurtosis kurtogram used to choose the band.
#ifndef OHMDEM_POST_ENVELOPE_H
#define OHMDEM_POST_ENVELOPE_H

#include <complex>
#include <cstddef>
#include <vector>

namespace ohmdem::post {

struct Band {
  double lo = 0;  // Hz
  double hi = 0;  // Hz; <= 0 means the Nyquist frequency
};

// |z| with z the analytic signal of x restricted to [lo, hi]: one r2c transform, the band's
// positive frequencies doubled (DC and Nyquist kept once, as scipy.signal.hilbert), one inverse
// c2c transform. The full band [0, fs/2] reproduces |scipy.signal.hilbert(x)|.
std::vector<double> envelope(const std::vector<double> &x, double rate, Band band);

// The end-zone treatment shared by the kurtogram and the band_sk detection test. A transform
// sees the record as periodic: the jump between its end and its start leaks into every band as
// an impulse at the edges, large where the spectrum falls steeply (red noise, strong shaft
// lines) and dominant in a nearly empty band (just below Nyquist at 48 kHz). The line through
// the means of the first and last 1/32 of the record removes the low-frequency part of the jump
// (end_jump_removed), and the complex envelope's end_guard(m) samples at each end, where the
// rest of it rings, are left out of the statistic.
std::vector<double> end_jump_removed(const std::vector<double> &x);
inline std::size_t end_guard(std::size_t m)
{
  return (m + 31) / 32;
}

struct KurtogramCell {
  int bands = 0;  // number of equal bands the level splits [0, fs/2] into
  double lo = 0, hi = 0;
  double kurtosis = 0;  // spectral kurtosis E|c|^4 / (E|c|^2)^2 - 2 of the complex envelope c
  // M, samples of the complex envelope kept (FFT bins in the band less 2 end_guard)
  std::size_t samples = 0;
};

struct Kurtogram {
  std::vector<KurtogramCell> cells;  // every band of every level, by level then frequency
  KurtogramCell best;                // largest spectral kurtosis
  // Significance of the best band: its SK exceeds the level a Gaussian record
  // reaches with probability alpha / cells.size() in that band (Bonferroni over the bands
  // searched), so a noise record's best band is called significant with probability <= alpha.
  double alpha = 0.01;
  double threshold = 0;      // sk_threshold(best.samples, alpha / cells.size())
  bool significant = false;  // best.kurtosis > threshold
};

// Upper alpha-quantile of the spectral kurtosis estimate M sum|c|^4 / (sum|c|^2)^2 - 2 of M
// independent circular complex Gaussian samples (white Gaussian noise in the band). Then
// |c|^2 / sum|c|^2 are uniform spacings, so SK + 2 = M G with G Greenwood's statistic, whose
// first three moments are exact (Dirichlet moments): E G = 2/(M+1),
// E G^2 = 4 (M+5) / ((M+1)(M+2)(M+3)),
// E G^3 = (720 + 144 (M-1) + 8 (M-1)(M-2)) / ((M+1)...(M+5)); sd(SK) -> 2/sqrt(M) (Antoni).
// The quantile is the larger of the Pearson type III (Wilson-Hilferty, three moments) and the
// Cornish-Fisher (four moments) ones: the skewness matters (1.1 at M = 64) and the normal
// 2/sqrt(M) z_alpha under-estimates the tail. Checked against Monte Carlo
// (doc/methods/spectral_analysis.md): the exceedance rate is 0.2 to 1.2 alpha for M >= 16,
// alpha in [2e-5, 0.05].
double sk_threshold(std::size_t m, double alpha);

// Levels split [0, fs/2] into 1, 2, 3, 4, 6, 8, 12, ... bands (the 1/3-binary tree of Antoni's
// fast kurtogram) with ideal FFT-domain filters; the complex envelope of a band is the inverse
// transform of its bins shifted to baseband. Stops at 2^max_level bands or when a band would be
// narrower than min_bandwidth (Hz). Bands entirely below fmin (Hz) are skipped. The record's
// end jump is treated as by band_sk (end_jump_removed, end_guard): a band's kurtosis is the
// value the detection test computes for it.
Kurtogram kurtogram(const std::vector<double> &x, double rate, int max_level, double min_bandwidth,
                    double fmin = 0, double alpha = 0.01);
// The same (fmin 0, alpha 0.01), and the best band's complex envelope at baseband, ends
// included, into best_envelope: the band_sk test's, which then need not transform the record
// again.
Kurtogram kurtogram(const std::vector<double> &x, double rate, int max_level, double min_bandwidth,
                    std::vector<std::complex<double>> &best_envelope);

}  // namespace ohmdem::post

#endif
