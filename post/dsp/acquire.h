// SPDX-License-Identifier: GPL-2.0-or-later
// The measurement chain of an instrument: what a data acquisition system records of a signal.
// In order: scale and offset (sensor sensitivity, e.g. the injected current turning R into a
// voltage), anti-alias Butterworth low-pass at the input rate, sampling at the instrument's
// rate (every k-th sample when the rate divides the input rate, else cubic interpolation),
// additive white Gaussian noise, ADC (clipping to the range, mid-tread rounding). Every step is
// optional; with none the output is the input.
#ifndef OHMDEM_POST_ACQUIRE_H
#define OHMDEM_POST_ACQUIRE_H

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/sampled_signal.h"
#include "dsp/butterworth.h"

namespace ohmdem::post {

struct AcquireSettings {
  double scale = 1, offset = 0;  // y = scale * x + offset
  double lowpass = 0;            // anti-alias cut-off (Hz, -3 dB); 0 = no filter
  int order = 4;                 // Butterworth order
  bool steady_start = true;      // filter state as if x[0] had lasted forever; false: zero
  double rate = 0;               // instrument sampling rate (Hz); 0 = the input's
  double noise_rms = 0;          // white noise rms per sample (output unit)
  double noise_density = 0;      // or its one-sided density (unit/sqrt(Hz)) over 0..rate/2
  std::uint64_t seed = 1;
  int bits = 0;           // ADC resolution; 0 = no ADC
  double lo = 0, hi = 0;  // ADC input range
};

// Throws SettingError naming the setting ("{acquire.rate}") for an impossible one.
void validate(const AcquireSettings &s, double input_rate);

struct Acquisition {
  Signal signal;               // the record (t0 = the input's first time)
  Sos filter;                  // the anti-alias filter's sections (empty without a low-pass)
  std::size_t decimation = 0;  // k when every k-th sample was taken; 0 when interpolated
  double noise_sigma = 0;      // rms of the added noise
  double q = 0;                // ADC step (HI - LO) / 2^bits
  std::size_t clipped = 0;     // samples outside the ADC's codes
  std::vector<std::string> warnings;
};

Acquisition acquire(const Signal &in, const AcquireSettings &s);

// --- the steps, exposed for the tests

// Whether fs_in / rate is an integer (to 1e-6 relative); returns it, else 0.
std::size_t integer_ratio(double fs_in, double rate);
// x[0], x[k], x[2k], ...
std::vector<double> take_every(const std::vector<double> &x, std::size_t k);
// x (unit spacing) at positions 0, step, 2 step, ... <= size-1, by 4-point Lagrange (cubic)
// interpolation on the samples around each position (the stencil shifted inside at the ends).
std::vector<double> interpolate_cubic(const std::vector<double> &x, double step);
// Largest error of interpolate_cubic on a tone of unit amplitude at f (fs = the input rate):
// |x''''| h^4 max|(u+1)u(u-1)(u-2)|/4! = (3/128) (2 pi f / fs)^4 (reached mid-way).
double cubic_interpolation_error(double f, double fs);

// Standard normal deviates from std::mt19937_64 (fully specified by the C++ standard) by the
// Box-Muller transform, so a seed gives the same sequence with any standard library.
class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}
  double next();

 private:
  double uniform();  // in (0, 1]
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

// Levels lo + k q, k = 0 .. 2^bits - 1, q = (hi - lo) / 2^bits (for a range symmetric about 0,
// 0 is a level: mid-tread); each value goes to the nearest level, ties up: k = floor((v-lo)/q +
// 1/2). A k outside the codes (v < lo - q/2 or v >= hi - q/2) is clipped to the end code.
// Returns the number clipped.
std::size_t quantize(std::vector<double> &x, int bits, double lo, double hi);

}  // namespace ohmdem::post

#endif
