// SPDX-License-Identifier: GPL-2.0-or-later
// Sampling laws of detection statistics under the Gaussian law (kurtosis, crest factor,
// spectral kurtosis) and the Student t law of the baseline bounds: p-values and thresholds,
// each checked against scipy.stats (tests/post/dsp/test_detect.cpp).
#ifndef OHMDEM_POST_DETECT_LAWS_H
#define OHMDEM_POST_DETECT_LAWS_H

namespace ohmdem::post {

double normal_sf(double z);                 // P(Z > z), Z ~ N(0, 1)
double normal_isf(double p);                // z with P(Z > z) = p, 0 < p < 1
double student_t_sf(double t, double nu);   // P(T_nu > t)
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

// Throws SettingError naming `what` (a setting as "{group.field}", or a function) unless
// 0 < p < 1.
double check_probability(double p, const char *what);

}  // namespace ohmdem::post

#endif
