// SPDX-License-Identifier: GPL-2.0-or-later
// Two channels: a sensor on each bearing of a shaft (the CWRU drive- and fan-end
// accelerometers) hears both bearings; a defect's impulses reach the far sensor through the
// housing, weaker. When this channel's impulses are coherent with the other channel's and stand
// out more there, they are the other bearing's: this bearing reads `none` (impulses from the
// other channel), or `other-bearing` when that bearing's family is identified.
#ifndef OHMDEM_POST_OTHER_CHANNEL_H
#define OHMDEM_POST_OTHER_CHANNEL_H

#include <string>
#include <vector>

#include "bearing/diagnose.h"

namespace ohmdem::post {

// Where the impulses are stronger: a defect's impulses stand out of the background most at the
// sensor nearest them (through the housing they arrive attenuated, under the far sensor's own
// background): the channel with the larger excess kurtosis (kurtosis - 3, 0 for Gaussian
// noise, a sine's -1.5) is the nearer. Absolute amplitudes are not compared: the two sensors
// differ in their mounting resonances (the CWRU fan-end sensor is louder above 4.5 kHz).
struct ChannelComparison {
  std::vector<double> lines_hz;  // this channel's strongest envelope lines (the shared lines)
  double coherence = 0;          // mean magnitude-squared coherence of the envelopes there
  double coherence_chance = 0;   // what independent envelopes give (Welch: 1 / segments)
  double this_excess = 0;        // excess kurtosis of this channel
  double other_excess = 0;       // of the other channel
  // coherent at the lines, and at least twice as impulsive on the other channel
  bool transmitted() const;
  std::string describe() const;
};

// This channel x against the other channel y (same rate and length), both enveloped in this
// channel's band: the envelope lines between f_lo and f_hi (Hz) that stand out of this
// channel's floor, their coherence, and each channel's excess kurtosis.
ChannelComparison compare_channels(const std::vector<double> &x, const std::vector<double> &y,
                                   double rate, Band band, double f_lo, double f_hi);

// A flagged record (unidentified or ambiguous: no family of this bearing named) whose impulses
// came from the other channel: `none` with candidate "other channel", or `other-bearing` when
// the other bearing's best comb scores. Named families are never changed.
void attribute_to_other_channel(Diagnosis &d, const ChannelComparison &c, double min_score);

}  // namespace ohmdem::post

#endif
