// SPDX-License-Identifier: GPL-2.0-or-later
// Order tracking: a signal sampled uniformly in time is resampled at constant increments of the
// shaft angle, so that lines tied to the shaft (orders: cycles per revolution, such as the
// defect families BPFI/fr, BPFO/fr, 2 BSF/fr, FTF/fr) stay sharp while the speed varies. The
// angle comes from an angle column or from a speed column by cumulative trapezoid integration.
// The order spectrum is then the ordinary spectrum with "samples per revolution" as the rate.
#ifndef OHMDEM_POST_ORDER_TRACKING_H
#define OHMDEM_POST_ORDER_TRACKING_H

#include <cstddef>
#include <string>
#include <vector>

namespace ohmdem::post {

enum class SpeedUnit { RadPerS, Rpm, Hz };
SpeedUnit parse_speed_unit(const std::string &name);  // "rad/s", "rpm", "hz" (Hz)
const char *speed_unit_name(SpeedUnit u);
// Speed in rad/s.
double to_rad_per_s(double v, SpeedUnit u);

// Shaft angle (rad) from speed samples omega (rad/s) at `rate` Hz: cumulative trapezoid,
// theta[0] = 0 (scipy.integrate.cumulative_trapezoid with initial=0).
std::vector<double> angle_from_speed(const std::vector<double> &omega, double rate);
// The angle 2 pi fr i / rate (rad) of n samples at a constant shaft frequency fr (Hz).
std::vector<double> constant_speed_angle(std::size_t n, double rate, double fr);

// Shaft speed summary from the angle: mean speed (rad/s) over `blocks` equal blocks of the
// record (block angle / block duration, insensitive to the printing resolution of the angle),
// and the relative spread (max - min) / mean of those block speeds.
struct SpeedSummary {
  double mean = 0, min = 0, max = 0;  // rad/s
  double variation = 0;               // (max - min) / mean
};
SpeedSummary speed_summary(const std::vector<double> &theta, double rate, std::size_t blocks = 16);

struct AngleResampled {
  std::vector<double> x;       // the signal at theta0 + k dtheta, k = 0..n-1
  double samples_per_rev = 0;  // the "sampling rate" of x in orders
  double theta0 = 0;           // angle of x[0] (rad, the angle column's origin)
  double t0 = 0;               // time of x[0] (s, from the start of the input)
  double flat_order = 0;       // orders below this are passed unchanged (kernel passband)
  double revolutions() const;  // x.size() / samples_per_rev
};

// Band-limited resampling at constant angle increments 2 pi / samples_per_rev. Each output
// sample is a Kaiser-windowed sinc sum of the input around its time t_k (theta(t_k) = theta_k,
// found by linear interpolation of the angle between samples) with the cut-off at the angle
// domain's Nyquist order samples_per_rev/2 expressed in Hz at the local speed (or the input's
// Nyquist frequency fs/2 when lower): the same kernel interpolates and removes, before they can
// alias, the components above the order bandwidth. Passband flat to 1e-4 up to 0.8 x the
// cut-off, stopband >= 100 dB from 1.2 x the cut-off (beta 10, 16 zero crossings each side).
// Output samples whose kernel would reach past the record's ends are not produced. theta must
// increase strictly (the shaft turns one way); Error otherwise, or if fewer than 16 samples
// result.
AngleResampled resample_by_angle(const std::vector<double> &x, double rate,
                                 const std::vector<double> &theta, double samples_per_rev);

// Default samples per revolution: as many output samples as input samples at the mean speed,
// fs / fr_mean, rounded up to an even integer, at least 16.
double default_samples_per_rev(double rate, double mean_omega);

// Times (s, from the start of the input) at which the shaft angle reaches the values of a
// resampled record: t_k for theta0 + k dtheta; used to map order-domain results back to time.
double time_at_angle(const std::vector<double> &theta, double rate, double angle);

}  // namespace ohmdem::post

#endif
