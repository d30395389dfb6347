// Fault detection, the first stage of `diagnose`: is the signal unlike a healthy one, whatever
// the defect? Statistics with explicit thresholds at a stated false-alarm probability per test:
// against the Gaussian law (kurtosis, crest factor, spectral kurtosis of the envelope band) and,
// given a healthy reference record, against that record's window-to-window scatter.
#ifndef OHMDEM_POST_DETECT_H
#define OHMDEM_POST_DETECT_H

#include <cstddef>
#include <string>
#include <vector>

#include "envelope.h"

namespace ohmdem::post {

// ---- the Gaussian law and its sampling distributions (each checked against scipy.stats)
double normal_sf(double z);   // P(Z > z), Z ~ N(0, 1)
double normal_isf(double p);  // z with P(Z > z) = p, 0 < p < 1
double student_t_isf(double p, double nu);  // t with P(T_nu > t) = p

// Anscombe-Glynn (1983) normal approximation of Pearson's sample kurtosis b2 = m4/m2^2 of n
// independent normal values (scipy.stats.kurtosistest): its z, and the one-sided p-value
// P(B2 >= b2). Where the cube-root transform is undefined (b2 far below 3) p is 1.
double kurtosis_z(double b2, double n);
double kurtosis_sf(double b2, double n);
double kurtosis_threshold(double n, double p);  // b2 with kurtosis_sf = p

// Crest factor max|x|/sigma of n normal values: P(crest > u) for independent values, and the
// u with that probability p. By Sidak's inequality P(all |x_i| <= u) >= prod P(|x_i| <= u) for
// any correlation, so these are bounds for any stationary Gaussian record of n samples.
double crest_sf(double u, double n);
double crest_threshold(double n, double p);

// Spectral kurtosis SK = E|c|^4/(E|c|^2)^2 - 2 of m independent circular complex normal
// values c: SK + 2 = m sum D_i^2 with D uniform on the simplex (Greenwood's statistic), whose
// first three moments are exact; the tail is that of the shifted gamma law with those moments
// (Wilson-Hilferty cube root). One-sided p-value and threshold.
double spectral_kurtosis_sf(double sk, double m);
double spectral_kurtosis_threshold(double m, double p);

// Independent samples worth of a record for fourth-moment statistics: n / sum_k (1 - |k|/n)
// rho_k^4 over all lags (the variance of the sample kurtosis of a stationary Gaussian record is
// 24/n sum_k rho_k^4). Lines (deterministic components) raise rho and lower the count.
double kurtosis_effective_samples(const std::vector<double> &x_centered);

// ---- the detection stage
struct DetectionTest {
  std::string name;       // kurtosis, crest, band_sk; baseline_rms, baseline_kurtosis, ...
  std::string reference;  // "gaussian" or "baseline"
  double value = 0;       // the statistic of the record
  double threshold = 0;   // fires when value > threshold
  double p_value = 0;     // under the reference law (NaN if not computed)
  double samples = 0;     // independent samples (gaussian) or record windows (baseline)
  bool applicable = true; // false: not evaluated (why in note)
  bool fired = false;
  std::string note;
};

struct DetectOptions {
  double false_alarm = 1e-3;     // per test
  Band band;                     // envelope band tested by band_sk (and band energy)
  std::size_t bands_searched = 1;  // kurtogram cells the band was chosen among (Bonferroni)
  std::size_t baseline_windows = 16;  // the baseline is split into this many windows
};

struct Detection {
  bool fired = false;       // any applicable test fired
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
// 1 for white noise, 0.16..0.96 for the measured CWRU records, 1e-9..2e-6 for the simulator's
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
