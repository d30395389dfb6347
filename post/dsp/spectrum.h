// SPDX-License-Identifier: GPL-2.0-or-later
// One-sided spectra of a real signal through FFTW: amplitude (a sine of amplitude A reads A at
// its bin, window coherent gain corrected), power (A^2/2 per sine, sums to the mean square) or
// power spectral density (ENBW corrected, unit^2/Hz). Detrending, zero padding and Welch
// averaging (power averaged over segments).
#ifndef OHMDEM_POST_SPECTRUM_H
#define OHMDEM_POST_SPECTRUM_H

#include <cstddef>
#include <string>
#include <vector>

#include "dsp/window.h"

namespace ohmdem::post {

enum class Detrend { None, Mean, Linear };
enum class Scaling { Amplitude, Power, Psd };

Detrend parse_detrend(const std::string &name);
const char *detrend_name(Detrend d);
Scaling parse_scaling(const std::string &name);
const char *scaling_name(Scaling s);
const char *scaling_unit(Scaling s);  // "" (signal unit), "^2", "^2/Hz"

struct SpectrumOptions {
  WindowKind window = WindowKind::Hann;
  Detrend detrend = Detrend::Mean;
  Scaling scaling = Scaling::Amplitude;
  std::size_t segment = 0;  // Welch segment length in samples; 0 = the whole signal
  double overlap = 0.5;     // Welch overlap fraction in [0, 1)
  std::size_t pad = 1;      // zero padding factor: nfft = pad x segment
  std::size_t nfft = 0;     // explicit transform length (>= segment); overrides pad
};

struct Spectrum {
  double df = 0;              // bin spacing (Hz)
  std::vector<double> value;  // per bin k (frequency k df), k = 0..nfft/2
  Scaling scaling = Scaling::Amplitude;
  WindowKind window = WindowKind::Hann;
  std::size_t segment = 0, nfft = 0, segments = 0;
  double enbw_hz = 0;  // equivalent noise bandwidth of one bin (Hz)
  double rate = 0;

  double frequency(std::size_t k) const { return static_cast<double>(k) * df; }
  std::size_t bins() const { return value.size(); }
};

Spectrum spectrum(const std::vector<double> &x, double rate, const SpectrumOptions &opt);

// Removes the mean or the least-squares line in place.
void detrend(double *x, std::size_t n, Detrend d);

}  // namespace ohmdem::post

#endif
