// SPDX-License-Identifier: GPL-2.0-or-later
// Peaks of a spectrum: local maxima standing out of a running-median noise floor, with the
// frequency and amplitude interpolated from the window's exact transform.
#ifndef OHMDEM_POST_PEAKS_H
#define OHMDEM_POST_PEAKS_H

#include <cstddef>
#include <limits>
#include <vector>

#include "dsp/spectrum.h"

namespace ohmdem::post {

struct Peak {
  double frequency = 0;      // Hz (interpolated)
  double value = 0;          // in the spectrum's scaling (interpolated)
  std::size_t bin = 0;       // bin of the local maximum
  double prominence_db = 0;  // 20 log10(amplitude / noise floor)
};

struct PeakOptions {
  std::size_t max_peaks = 10;
  double min_prominence_db = 6;
  double fmin = 0;
  double fmax = std::numeric_limits<double>::infinity();
  bool interpolate = true;
};

// Noise floor (amplitude units) per bin: medians of blocks of `block` bins (half-overlapping),
// interpolated linearly between block centres.
std::vector<double> noise_floor(const std::vector<double> &amplitude, std::size_t block);
// Block size used by find_peaks and diagnose: 64 unpadded bins (at least 16 bins).
std::size_t default_floor_block(const Spectrum &s);

// Amplitude (signal units) of bin k whatever the spectrum's scaling.
double amplitude_of(const Spectrum &s, std::size_t k);

// Sorted by decreasing value.
std::vector<Peak> find_peaks(const Spectrum &s, const PeakOptions &opt);

// Interpolates the peak at local maximum k: solves |X(k+s)|/|X(k)| = K(1-d)/K(d) for the offset
// d with the window kernel K, amplitude |X(k)|/K(d). Exact for an isolated stationary sine.
Peak refine_peak(const Spectrum &s, std::size_t k);

}  // namespace ohmdem::post

#endif
