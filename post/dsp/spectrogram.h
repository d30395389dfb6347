// SPDX-License-Identifier: GPL-2.0-or-later
// Short-time amplitude spectrum of a record as an image: the amplitude spectrum of segments
// of a fixed length, hopping along the record, in dB.
#ifndef OHMDEM_POST_SPECTROGRAM_H
#define OHMDEM_POST_SPECTROGRAM_H

#include <cstddef>
#include <vector>

#include "core/sampled_signal.h"
#include "dsp/window.h"

namespace ohmdem::post {

struct SpectrogramOptions {
  std::size_t segment = 0;  // samples per segment; 0: spectrogram_segment(n)
  WindowKind window = WindowKind::Hann;
  double fmin = 0, fmax = 0;      // the rows shown (Hz); each segment's mean is removed
  std::size_t max_columns = 400;  // the hop grows beyond a quarter segment to stay below
  std::size_t max_rows = 600;     // neighbouring bins are grouped (largest kept) to stay below
  double range_db = 100;          // values below the peak minus this are raised to it
};

struct Spectrogram {
  std::size_t segment = 0, hop = 0;
  double df = 0;           // bin spacing (Hz)
  std::vector<double> t;   // centre of each column's segment (s)
  std::vector<double> f;   // frequency of each row's first bin (Hz)
  std::vector<double> db;  // 20 log10 amplitude, row-major: db[row * t.size() + column]
  std::size_t first(std::size_t column) const { return column * hop; }  // segment's 1st sample
};

// A power of two near n/64 in [64, 8192] (at most n).
std::size_t spectrogram_segment(std::size_t n);

// Throws Error when no bin lies in [fmin, fmax] or the segment is not 4..n samples.
Spectrogram spectrogram(const Signal &s, const SpectrogramOptions &o);

// The mean shaft frequency (Hz) over each column's segment, from the shaft angle (rad) of
// every sample of the record.
std::vector<double> segment_shaft_hz(const Spectrogram &sg, const std::vector<double> &theta,
                                     double rate);

}  // namespace ohmdem::post

#endif
