// SPDX-License-Identifier: GPL-2.0-or-later
// A race comb: a defect's pulse train or a smooth modulation? A loaded healthy
// bearing's compliance varies as its balls pass the load zone: a nearly sinusoidal modulation
// at BPFO, whose comb is its fundamental with fast-falling harmonics and whose record stays
// below a Gaussian's kurtosis. A defect's short pulses make a comb whose harmonics fall slowly
// (a pulse of duty d: sinc(h d)) and a super-Gaussian record. Two discriminators, used together.
#ifndef OHMDEM_POST_PULSE_TRAIN_H
#define OHMDEM_POST_PULSE_TRAIN_H

#include "bearing/diagnose.h"

namespace ohmdem::post {

// The comb's harmonic content: (A2 + A3) / (2 A1), the mean amplitude of its 2nd and 3rd
// harmonics over the fundamental's on the spectrum it was scored on (a harmonic not found
// counts 0; NaN without a fundamental or with fewer than 3 harmonics scored).
double harmonic_ratio(const FamilyScore &f);

// Below this kurtosis a record holds no pulse train by the first discriminator: a smooth
// modulation (a sine: 1.5) plus independent Gaussian noise (3) stays below 3, a pulse train
// (super-Gaussian) plus noise above it. Measured race faults: 3.06 to 51; healthy radially
// loaded 6208s at 20 kHz: 1.5 to 2.71.
constexpr double kSmoothKurtosis = 3.0;
// At or above this harmonic ratio a comb is a pulse train by the second: a rectangular pulse of
// duty d gives (sinc(2d) + sinc(3d)) / (2 sinc(d)), 0.5 at d = 0.25 (pulses shorter than a
// quarter of the period lie above); a sawtooth (harmonics 1/h, kurtosis 1.8) 0.42. Measured: the
// healthy radial 6208s (300 to 700 rad/s, 160 to 640 N, their comb in the raw spectrum) 0.05 to
// 0.19; weak race faults of the independent model (tests/post/synthetic_bearing.py, -6 and
// -12 dB, kurtosis within 0.1 of 3) 0.37 to 0.81, outer races 0.6 to 0.7; CWRU race faults 0.25
// to 10 (sig14, kurtosis 3.06: 10.3).
constexpr double kPulseHarmonics = 0.5;

// The two together: a smooth modulation has a kurtosis below 3 and a comb whose harmonics stand
// below kPulseHarmonics of its fundamental (or too few harmonics to tell).
bool smooth_modulation(double kurtosis, const FamilyScore &f);

}  // namespace ohmdem::post

#endif
