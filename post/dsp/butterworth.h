// SPDX-License-Identifier: GPL-2.0-or-later
// Digital Butterworth low-pass filters as second-order sections, designed as
// scipy.signal.butter(N, fc, fs=fs, output='sos') does (analog prototype poles, bilinear
// transform with the cut-off prewarped, 'nearest' pole-zero pairing, gain in the first section),
// and applied as sosfilt does (cascaded direct-form-II-transposed biquads).
#ifndef OHMDEM_POST_BUTTERWORTH_H
#define OHMDEM_POST_BUTTERWORTH_H

#include <array>
#include <complex>
#include <vector>

namespace ohmdem::post {

// One section: H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2), scipy's sos row
// [b0, b1, b2, 1, a1, a2].
struct Biquad {
  double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};
using Sos = std::vector<Biquad>;

// Order 1..kMaxButterworthOrder, 0 < fc < fs/2 (Error otherwise). -3 dB at fc exactly.
constexpr int kMaxButterworthOrder = 20;
Sos butterworth_lowpass(int order, double fc, double fs);

// Filter state of each section (scipy's zi, shape (sections, 2)).
using SosState = std::vector<std::array<double, 2>>;
SosState sos_zero_state(const Sos &sos);
// The state after a constant input `x0` forever (scipy.signal.sosfilt_zi(sos) * x0): the
// filtered output then starts at H(0)*x0 without a start-up transient.
SosState sos_steady_state(const Sos &sos, double x0);

// Filters x in place, updating `state`.
void sos_filter(const Sos &sos, std::vector<double> &x, SosState &state);

// Frequency response H(e^{i 2 pi f / fs}) of the cascade.
std::complex<double> sos_response(const Sos &sos, double f, double fs);

// The cascade's group delay at 0 Hz (s): per section (b1 + 2 b2) / (b0 + b1 + b2) - (a1 + 2 a2)
// / (1 + a1 + a2) samples (the phase of sum c_k e^{-i w k} falls as w sum k c_k / sum c_k near
// w = 0), summed, over fs.
double sos_dc_delay_s(const Sos &sos, double fs);

// The cascade's group delay at f (s): per section Re(sum k b_k z^-k / sum b_k z^-k) less the
// same of the denominator, z = e^{i 2 pi f / fs}, summed, over fs (-d phase / d omega of each
// polynomial; at f = 0 what sos_dc_delay_s gives).
double sos_group_delay_s(const Sos &sos, double f, double fs);

// A record's anti-alias filter as its header states it: the sections and the rate they run at.
struct RecordFilter {
  Sos sos;
  double fs = 0;
};

// |H(f)| of the digital Butterworth low-pass in closed form (bilinear transform of the analog
// |H| = 1/sqrt(1 + (w/wc)^2N), with the prewarped frequencies tan(pi f/fs)): the theory the
// design is checked against.
double butterworth_gain(int order, double fc, double fs, double f);

}  // namespace ohmdem::post

#endif
