// SPDX-License-Identifier: GPL-2.0-or-later
// Synthetic test signals: resistance-like rectangle trains of each defect kind (the shape our
// engine writes), sines, impulse trains through a resonance, Gaussian noise. Deterministic:
// a fixed-seed mt19937_64 and our own Box-Muller (std::normal_distribution is not portable).
#ifndef OHMDEM_TESTS_POST_SYNTH_H
#define OHMDEM_TESTS_POST_SYNTH_H

#include <cstdint>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "core/sampled_signal.h"

namespace ohmdem::post::test {

class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed);
  double operator()();  // N(0, 1)

 private:
  std::uint64_t state_;
  double next_uniform();
};

struct DefectSpec {
  std::string kind = "inner";  // inner, outer, ball, cage, none
  double omega_inner = 500;    // rad/s
  double rate = 1e6;           // Hz
  double duration = 0.2;       // s
  double level = 1.39;         // ohm
  double step = 0.083;         // relative rise while a path is broken
  double size_deg = 1.0;       // defect size: sets the pulse width from the kinematics
  double snr_db = 1e9;         // signal (AC power of the clean train) to white noise; 1e9 = none
  double modulation = 0.6;     // ball: amplitude modulation depth at FTF
  double slip = 0;             // relative reduction of the repetition frequency
  std::uint64_t seed = 1;
};

struct DefectSignal {
  Signal signal;
  double frequency = 0;  // repetition frequency used (Hz)
  double width_s = 0;    // pulse width used (s)
  double noise_sigma = 0;
};

// A rectangle train: level, +step while the defect is in contact, repeating at BPFI (inner),
// BPFO (outer), 2 BSF (ball, amplitude modulated at FTF) or FTF (cage, for vibration-like tests),
// pulse width from the size: inner size/(omega_i - omega_c), outer size/omega_c,
// ball size/(2 pi BSF).
DefectSignal defect_signal(const BearingGeometry &g, const DefectSpec &spec);

std::vector<double> sine(std::size_t n, double rate, double f, double amplitude, double phase);

}  // namespace ohmdem::post::test

#endif
