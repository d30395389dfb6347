// Envelope analysis: ideal band-pass in the frequency domain and Hilbert transform through
// FFTW (|analytic signal|), and the fast spectral-kurtosis kurtogram used to choose the band.
#ifndef OHMDEM_POST_ENVELOPE_H
#define OHMDEM_POST_ENVELOPE_H

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

struct KurtogramCell {
  int bands = 0;  // number of equal bands the level splits [0, fs/2] into
  double lo = 0, hi = 0;
  double kurtosis = 0;  // spectral kurtosis E|c|^4 / (E|c|^2)^2 - 2 of the complex envelope c
};

struct Kurtogram {
  std::vector<KurtogramCell> cells;  // every band of every level, by level then frequency
  KurtogramCell best;                // largest spectral kurtosis
};

// Levels split [0, fs/2] into 1, 2, 3, 4, 6, 8, 12, ... bands (the 1/3-binary tree of Antoni's
// fast kurtogram) with ideal FFT-domain filters; the complex envelope of a band is the inverse
// transform of its bins shifted to baseband. Stops at 2^max_level bands or when a band would be
// narrower than min_bandwidth (Hz). Bands entirely below fmin (Hz) are skipped.
Kurtogram kurtogram(const std::vector<double> &x, double rate, int max_level, double min_bandwidth,
                    double fmin = 0);

}  // namespace ohmdem::post

#endif
