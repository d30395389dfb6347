// SPDX-License-Identifier: GPL-2.0-or-later
// An outer defect's angle from the load direction from a two-axis accelerometer.
// When a ball enters or leaves a pit of the outer race, its push on the ring changes along the
// pit's radius, so the ring's acceleration in the bearing's plane jumps along that line: the
// principal direction of the defect events' acceleration (their 2x2 covariance of the two
// axes, less the same of the background between the passes) is the pit's angle from the first
// axis, modulo 180 deg. A common linear filter (the anti-alias filter on both axes) keeps that
// direction, and noise of the same level on both axes adds the same to both variances, which
// the background's covariance takes off. The direction is a line: the angle is given in
// (-90, 90] deg from the first axis, on the load zone's side when that axis is along the load
// direction (the pit's signed angle from it, the second axis turned +90 deg); a pit beyond 90
// deg from the load, whose events the balls' centrifugal force still gives, reads 180 deg off.
// Plain C++, doc/methods/place_outer_two_axes.md.
#ifndef OHMDEM_POST_BEARING_EVENT_DIRECTION_H
#define OHMDEM_POST_BEARING_EVENT_DIRECTION_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

struct EventDirectionSettings {
  std::size_t groups = 10;   // groups of consecutive passes left out in turn (jackknife)
  double confidence = 0.95;  // two-sided level of the interval
  // Added to the interval's half width: how far the ring's response turns the events' direction
  // from the pit's (the simulated 6208 under a radial load: at most 2.5 deg over pits of
  // 0.3-3 deg, 0-45 deg from the load, 10-50 kHz; doc/methods/place_outer_two_axes.md).
  double model_deg = 3.0;
};

struct EventDirection {
  bool valid = false;
  std::string note;                                             // how, or why not determined
  double angle_deg = std::numeric_limits<double>::quiet_NaN();  // in (-90, 90]
  double half_width_deg = std::numeric_limits<double>::quiet_NaN();
  std::size_t passes = 0;
  double events_to_background = std::numeric_limits<double>::quiet_NaN();  // energies' ratio
};

// first and second: the two axes' accelerations, sampled together at `rate`; the defect's
// passes repeat at f (Hz). Throws std::invalid_argument for settings out of range or axes of
// different lengths.
EventDirection event_direction(const std::vector<double> &first, const std::vector<double> &second,
                               double rate, double f, const EventDirectionSettings &s);

struct Signal;
struct DiagnoseOptions;
struct RaceToSize;
struct DefectLocation;
// An outer defect's place from the load direction (position_reference "load direction") when
// the record's second axis is given (o.across) under a radial load; else l is left as it is.
void place_outer_by_event_direction(const Signal &s, const RaceToSize &r, const DiagnoseOptions &o,
                                    DefectLocation &l);

}  // namespace ohmdem::post

#endif
