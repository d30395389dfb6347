// SPDX-License-Identifier: GPL-2.0-or-later
// Rectangular pulses in a level signal (our R(t): a constant level with steps while a ball's
// path is broken): direct detection at half height, and a time-synchronous average at a known
// repetition frequency for noisy records. Used to estimate the defect size from pulse widths.
#ifndef OHMDEM_POST_PULSES_H
#define OHMDEM_POST_PULSES_H

#include <cstddef>
#include <string>
#include <vector>

namespace ohmdem::post {

struct PulseTrain {
  double baseline = 0;  // median of the signal
  double noise = 0;     // robust standard deviation (1.4826 MAD) around the baseline
  double height = 0;    // signed median plateau deviation of the pulses
  std::vector<double> start_s, width_s;  // every run beyond half height (s)
  double median_width_s = 0;             // over runs of at least 3 samples
  double median_spacing_s = 0;           // between starts of consecutive counted runs
  double width_spread = 0;               // interquartile range / median of the counted widths
  std::size_t counted = 0;               // runs of at least 3 samples
  bool clean = false;                    // >= 3 counted pulses, consistent widths, height > 6 noise
};

// Runs where polarity x (x - baseline) exceeds half the plateau height, merged across gaps of up
// to 2 samples; edges interpolated linearly at half height.
PulseTrain detect_pulses(const std::vector<double> &x, double rate);

struct AveragedPulse {
  double width_s = 0;      // full width at half maximum of the averaged pulse
  double height = 0;       // signed
  double contrast = 0;     // |height| / noise of the averaged waveform
  std::size_t cycles = 0;  // periods averaged
  bool valid = false;      // contrast >= 6 and width >= 2 samples
};

// Time-synchronous average of x folded at frequency f (Hz), then the width at half height of the
// deviation from the averaged waveform's median.
AveragedPulse synchronous_pulse(const std::vector<double> &x, double rate, double f);

// The repetition frequency near f (within +-1 period of drift over the record, 41 steps) whose
// synchronous average has the highest contrast: slip moves the defect's passes off f.
double refine_repetition(const std::vector<double> &x, double rate, double f);

// The repetition frequency near f (within two of refine_repetition's steps either side, f its
// answer) whose first harmonics (up to max_hz, at most 32) carry the most power: the Z^2
// statistic of pulse timing, smooth in the frequency where the contrast above is read on whole
// samples. refine_repetition's step drifts a fold by 1/20 of a period over the record, which
// smears a fold read at quarter samples; this one leaves under 1/10^4 of a period.
double refine_repetition_fine(const std::vector<double> &x, double rate, double f, double max_hz);

}  // namespace ohmdem::post

#endif
