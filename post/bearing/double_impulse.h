// SPDX-License-Identifier: GPL-2.0-or-later
// A race defect's size from an accelerometer record by the double-impulse method.
// A ball crossing a pit gives two events: the entry (the ball unloads as it rolls down the
// leading edge: a low-frequency step) and the exit (it is loaded again at the far edge: an
// impulse). Their delay times the ball's angular speed relative to the ring is the pit's angular
// size. The record is pre-whitened (the residual of an autoregressive model, which shortens the
// ring's resonances and balances the step against the impulse), its squared envelope is cut
// into one segment per defect pass centred on the pass's strongest event, and the autocorrelation
// of each segment, summed over the passes, has its secondary peak at the entry-exit delay.
#ifndef OHMDEM_POST_BEARING_DOUBLE_IMPULSE_H
#define OHMDEM_POST_BEARING_DOUBLE_IMPULSE_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

struct DoubleImpulseSettings {
  int ar_order = 0;    // pre-whitening order; 0: min(32, a quarter period), <0: none
  double band_lo = 0;  // envelope band (Hz); hi <= 0: the Nyquist frequency
  double band_hi = 0;
  std::size_t groups = 10;       // pass groups whose delays give the interval's scatter
  double confidence = 0.95;      // two-sided level of the interval
  double min_delay_samples = 2;  // below this the two events are one: not determined
  double min_contrast = 0.02;    // secondary peak over the dip before it, / the zero lag
};

struct DoubleImpulseSize {
  bool valid = false;
  std::string note;  // how, or why not determined
  double delay_s = std::numeric_limits<double>::quiet_NaN();
  double delay_lo_s = std::numeric_limits<double>::quiet_NaN();
  double delay_hi_s = std::numeric_limits<double>::quiet_NaN();
  double size_deg = std::numeric_limits<double>::quiet_NaN();
  double size_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double size_hi_deg = std::numeric_limits<double>::quiet_NaN();
  double contrast = 0;  // of the secondary peak (see min_contrast)
  std::size_t passes = 0;
};

// Averaged autocorrelation of the passes' squared envelopes (lags 0 .. a quarter period, divided
// by lag 0) and the number of passes: exposed for the tests and the studies.
struct PassAutocorrelation {
  std::vector<double> acf;
  std::vector<std::vector<double>> group_acf;  // the same per group of consecutive passes
  // the same from segments half a period after each pass (the background between passes)
  std::vector<double> background_acf;
  std::vector<std::vector<double>> group_background_acf;
  std::size_t passes = 0;
};
PassAutocorrelation pass_autocorrelation(const std::vector<double> &x, double rate, double f,
                                         const DoubleImpulseSettings &s);

// x an acceleration sampled at `rate`; the defect's passes repeat at f (Hz, BPFI or BPFO);
// defect "inner" or "outer"; nb balls. Throws std::invalid_argument for settings out of range.
DoubleImpulseSize size_from_double_impulse(const std::vector<double> &x, double rate, double f,
                                           const std::string &defect, int nb,
                                           const DoubleImpulseSettings &s);

struct Diagnosis;
struct DiagnoseOptions;
struct Signal;
struct DefectLocation;
// diagnose's size, interval and what stays open, by this method (diagnose's double-impulse
// size method): the race defect found (or o.assume_defect at its kinematic frequency).
DefectLocation locate_by_double_impulse(const Signal &s, const Diagnosis &found,
                                       const DiagnoseOptions &o);

// Residual of the order-p autoregressive model of x (Levinson-Durbin on its autocorrelation).
std::vector<double> ar_residual(const std::vector<double> &x, int p);

}  // namespace ohmdem::post

#endif
