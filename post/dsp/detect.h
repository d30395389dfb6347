// SPDX-License-Identifier: GPL-2.0-or-later
// Fault detection, the first stage of `diagnose`: is the signal unlike a healthy one, whatever
// the defect? Statistics with explicit thresholds at a stated false-alarm probability per test:
// against the Gaussian law (kurtosis, crest factor, spectral kurtosis of the envelope band) and,
// given a healthy reference record, against that record's window-to-window scatter.
#ifndef OHMDEM_POST_DETECT_H
#define OHMDEM_POST_DETECT_H

#include <cstddef>
#include <string>
#include <vector>

#include "dsp/detect_laws.h"
#include "dsp/envelope.h"

namespace ohmdem::post {

// Independent samples worth of a record for fourth-moment statistics: n / sum_k (1 - |k|/n)
// rho_k^4 over all lags (the variance of the sample kurtosis of a stationary Gaussian record is
// 24/n sum_k rho_k^4). Lines (deterministic components) raise rho and lower the count.
double kurtosis_effective_samples(const std::vector<double> &x_centered);

// ---- the detection stage
struct DetectionTest {
  std::string name;        // kurtosis, crest, band_sk; baseline_rms, baseline_kurtosis, ...
  std::string reference;   // "gaussian" or "baseline"
  double value = 0;        // the statistic of the record
  double threshold = 0;    // fires when value > threshold
  double p_value = 0;      // under the reference law (NaN if not computed)
  double samples = 0;      // independent samples (gaussian) or record windows (baseline)
  bool applicable = true;  // false: not evaluated (why in note)
  bool fired = false;
  std::string note;
};

struct DetectOptions {
  double false_alarm = 1e-3;          // per test
  Band band;                          // envelope band tested by band_sk (and band energy)
  std::size_t bands_searched = 1;     // kurtogram cells the band was chosen among (Bonferroni)
  std::size_t baseline_windows = 16;  // the baseline is split into this many windows
  // the band's complex envelope as kurtogram() made it from this record (its best_envelope,
  // when the band is its best), or null: band_sk then transforms the record itself
  const std::vector<std::complex<double>> *band_envelope = nullptr;
};

struct Detection {
  bool fired = false;      // any applicable test fired
  double white_floor = 0;  // white noise floor / standard deviation (white_floor_ratio)
  bool gaussian_applicable = false;
  std::string gaussian_note;  // why the Gaussian tests are (not) applicable
  std::size_t tests_applied = 0;
  double false_alarm_bound = 0;  // union bound: tests_applied x false_alarm
  std::vector<DetectionTest> tests;
};

// The white noise floor of a record relative to its spread: the robust (median absolute) scale
// of its second differences over disjoint triples, (x_3i - 2 x_3i+1 + x_3i+2)/sqrt(6), over its
// standard deviation (a Donoho-Johnstone estimate with a filter blind to smooth content).
// 1 for white noise, 0.16..0.96 for the measured CWRU records, 7e-10..2e-6 for the simulator's
// R(t) (flat between contact events: round-off).
double white_floor_ratio(const std::vector<double> &x);
// Below this ratio (the white floor holds < 1e-6 of the variance) a record is deterministic at
// the precision of its numbers and the Gaussian tests do not apply (doc/ohmdem-post.md).
constexpr double kMinWhiteFloor = 1e-3;

// The detection stage on a record (mean removed) sampled at `rate`. `baseline` (mean removed,
// same rate), if not null, adds the tests against the healthy reference.
Detection detect(const std::vector<double> &x_centered, double rate, const DetectOptions &opt,
                 const std::vector<double> *baseline = nullptr);

}  // namespace ohmdem::post

#endif
