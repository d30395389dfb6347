// SPDX-License-Identifier: GPL-2.0-or-later
// A race defect's size from the area of its pulses in an electrical record. While a
// ball crosses the defect its path is broken and the level (R, or the instrument's voltage I R)
// jumps by h times its value, h being the bearing's own model of one path lost; the jump lasts
// tau = size / (angular speed of the ball relative to the ring). The anti-alias filter (unit
// gain at 0 Hz) and the sampling keep the pulse's area, so area / (h level) = tau at any rate
// that still sees the defect's passes. Every pass gives one area; the estimate is their mean
// (balanced loads, outer defects) or the peak of the load-zone curve they follow (an inner
// defect under a radial load), and its interval comes from the pass-to-pass scatter.
#ifndef OHMDEM_POST_BEARING_PULSE_AREA_H
#define OHMDEM_POST_BEARING_PULSE_AREA_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "bearing/load_zone_fit.h"

namespace ohmdem::post {

struct PulseAreaSettings {
  // h: relative level jump when the ball in the defect loses contact (under a radial load: at
  // the centre of the load zone). Must be > 0.
  double rel_height = 0;
  bool load_zone = false;    // radial load: pulse heights follow the load zone
  double level_offset = 0;   // the record's value at R = 0 (acquire's offset)
  double confidence = 0.95;  // two-sided level of the interval
  double fr = 0;             // shaft frequency (Hz): the inner defect turns with the shaft
  double load_direction_deg = kLoadDirectionDeg;  // where the load zone's centre is
  // shaft angle (rad) per sample, from the record (angle column or tachometer), else null:
  // an inner defect's position on the ring is then not determined
  const std::vector<double> *shaft_angle = nullptr;
  // the record's anti-alias filter's delay at 0 Hz (in the record's time unit): a pulse shows
  // this much after the ball crosses the pit, so a pass's shaft angle is read this much earlier
  double delay = 0;
  // The model's curve from simulations of the same scene: the mean over the passes
  // of the fixed-window area / level (window_rel_area_s below) against the size (deg), sizes
  // increasing, areas increasing. When given, the size is read off it (rel_height unused).
  std::vector<double> curve_size_deg, curve_rel_area_s;
  // The curve's own error (the model's, calibrated on simulations the cases never use): the
  // relative standard deviation of its area, combined with the pass-to-pass scatter in the
  // interval. With it, an interval reaching below the curve's first point extends to the origin
  // (area proportional to the size there); one reaching past its last point is open above.
  double curve_rel_error = 0;
};

// The fixed window: from 100 us before the pulse's start (the folded average's first bin beyond
// 2 % of its peak) to 500 us after it, the level the mean of the 200 us before the window. The
// simulated pulses do not end at the exit (the ring settles, the level dips and recovers), so
// the statistic must not depend on where the record's own pulse window ends. (A window of 0.6
// defect periods did worse: it takes in more of the load zone's modulation.)
constexpr double kWindowBefore = 100e-6, kWindowAfter = 500e-6, kWindowLevel = 200e-6;

struct PulseAreaSize {
  bool valid = false;
  std::string note;                   // how, or why not
  double tau_s = 0;                   // the pulse duration area / (h level)
  double tau_lo_s = 0, tau_hi_s = 0;  // its interval (hi = +inf when only a lower bound)
  double rel_area_s = 0;
  // mean and standard error over the passes of the fixed-window area / level (s)
  double window_rel_area_s = std::numeric_limits<double>::quiet_NaN(), window_se_s = 0;
  // from the model's curve (NaN without one; hi NaN: beyond the curve)
  double size_deg = std::numeric_limits<double>::quiet_NaN();
  double size_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double size_hi_deg = std::numeric_limits<double>::quiet_NaN();  // mean (or load-zone peak) of
                                                                  // area / level over the passes
  std::size_t passes = 0;
  // inner defect under a radial load with a shaft angle: the defect's angle on the ring from
  // the shaft's zero, degrees in [0, 360), and the fit's half-width (Student t at 95 % times
  // the jackknife's spread over the passes; the caller adds the model's part); NaN otherwise
  double position_deg = std::numeric_limits<double>::quiet_NaN();
  double position_half_deg = std::numeric_limits<double>::quiet_NaN();
  std::string position_note;  // why no place where the passes were fitted (else see note)
};

// x sampled at `rate`, its time of x[0] t0; pulses repeating at f (Hz); defect "inner"/"outer".
PulseAreaSize size_from_pulse_area(const std::vector<double> &x, double rate, double t0, double f,
                                   const std::string &defect, const PulseAreaSettings &s);

// Per-pass areas divided by the level before the pulse (s), and the pass times (s): exposed
// for the tests.
struct PassAreas {
  std::vector<double> rel_area, time;
};
// fixed: the fixed window (kWindow*) instead of the record's own pulse window
PassAreas pass_areas(const std::vector<double> &x, double rate, double t0, double f,
                     double level_offset, bool fixed = false);

}  // namespace ohmdem::post

#endif
