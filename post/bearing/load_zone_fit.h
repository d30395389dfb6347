// SPDX-License-Identifier: GPL-2.0-or-later
// An inner-race defect under a radial load turns with the shaft through the load zone: what a
// pass shows (the electrical pulse's area, the accelerometer's pass energy) peaks when the
// defect meets the load direction. A per-pass value r_j against the shaft angle theta_j at the
// pass is fitted by r_j = c cos^p(theta_j - phi) (0 outside the half turn): phi on a 1-degree
// grid, then at the vertex of the parabola through the best point's and its neighbours' fits,
// p in {1, 1.5, ..., 4}, c by least squares. The defect's place on the ring, from the
// shaft's zero, is then the load direction - phi. The pulse area (bearing/pulse_area.h) and the
// pass energy (bearing/pass_energy.h) share it.
#ifndef OHMDEM_POST_BEARING_LOAD_ZONE_FIT_H
#define OHMDEM_POST_BEARING_LOAD_ZONE_FIT_H

#include <cstddef>
#include <limits>
#include <vector>

namespace ohmdem::post {

// Where the radial load's zone is centred (deg; the deck's load along +y).
constexpr double kLoadDirectionDeg = 90;

// a - 360 floor(a / 360): the angle in [0, 360).
double wrap_deg(double a);

// The fit over every pass, and the jackknife's spread (each pass left out once).
struct ZoneEstimate {
  double c = 0, phi_deg = 0;  // over every pass
  double c_se = std::numeric_limits<double>::quiet_NaN();
  double phi_sd = std::numeric_limits<double>::quiet_NaN();
};
// theta (rad) and r of the same length n >= 2.
ZoneEstimate zone_estimate(const std::vector<double> &theta, const std::vector<double> &r);

// The shaft angle (rad) at times t (s; the record's first sample at t0): the record's angle
// per sample where it has one (accumulated: linear between the samples around t, the first or
// last sample beyond the record's ends), else 2 pi fr t.
std::vector<double> shaft_angles_at(const std::vector<double> &t, double rate, double t0,
                                    const std::vector<double> *shaft_angle, double fr);

}  // namespace ohmdem::post

#endif
