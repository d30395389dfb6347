// SPDX-License-Identifier: GPL-2.0-or-later
// Synthetic electrical records for the pulse-area and pulse-edge tests: a level of 0.05 (V = I R)
// with pulses 0.45 level high lasting tau at f (the first at phase 0.3), made at 1 MHz and
// acquired at `rate` through dsp/acquire's chain (Butterworth order 4 at 0.4 x rate, 1e-6 noise).
// With fr > 0 the height follows cos^2 of the shaft angle 2 pi fr t + position - 90 deg (an inner
// defect under a radial load, its zone's centre at 90 deg); with decay > 0 the jump falls to
// 40 % during the pulse with that time constant (the ring settling onto the other balls); `height`
// the pulse's height over the level (an outer pit farther from the load: a lower one).
#ifndef OHMDEM_TESTS_POST_BEARING_PULSE_RECORDS_H
#define OHMDEM_TESTS_POST_BEARING_PULSE_RECORDS_H

#include <cmath>

#include "dsp/acquire.h"
#include "test_constants.h"

namespace ohmdem::post::test_records {

inline Signal pulse_record(double tau, double f, double rate, double fr = 0,
                           double position_deg = 0, double decay = 0, double height = 0.45)
{
  const double fs = 1e6, level = 0.05, h = height, pi = ohmdem::test::kPi;
  Signal in;
  in.rate = fs;
  const std::size_t n = 300000;
  in.x.assign(n, level);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    const double u = std::fmod(t * f + 0.3, 1.0) / f;
    double k = 1;
    if (fr > 0) {
      const double c = std::cos(2 * pi * fr * t + (position_deg - 90) * pi / 180);
      k = c > 0 ? c * c : 0;
    }
    if (decay > 0) k *= 0.4 + 0.6 * std::exp(-u / decay);
    if (u < tau) in.x[i] += k * h * level;
  }
  AcquireSettings a;
  a.lowpass = 0.4 * rate;
  a.rate = rate;
  a.noise_rms = 1e-6;
  return acquire(in, a).signal;
}

}  // namespace ohmdem::post::test_records

#endif
