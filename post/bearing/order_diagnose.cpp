// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/order_diagnose.h"

#include "core/constants.h"
#include "core/error.h"
#include "dsp/order_tracking.h"

namespace ohmdem::post {

Diagnosis diagnose_in_orders(const Signal &s, const std::vector<double> &theta, DiagnoseOptions opt,
                             double samples_per_rev)
{
  // the other sensor's samples would have to be resampled at the same angles: not done
  if (opt.other_channel)
    throw SettingError(
        "{diagnose.other_channel} is not supported when the speed varies (the record is "
        "diagnosed in the angle domain); give a record at constant speed");
  constexpr double kTwoPi = 2 * kPi;
  const SpeedSummary speed = speed_summary(theta, s.rate);
  const double fr = speed.mean / kTwoPi;  // mean shaft frequency (Hz)
  const double spr =
      samples_per_rev > 0 ? samples_per_rev : default_samples_per_rev(s.rate, speed.mean);
  const AngleResampled r = resample_by_angle(s.x, s.rate, theta, spr);
  Signal a;
  a.x = r.x;
  a.rate = spr;  // samples per revolution: frequencies below are orders
  a.t0 = r.theta0 / kTwoPi;
  a.name = s.name;
  opt.fr = 1;
  // the filter's delay in the resampled record's unit, revolutions, at the mean speed (the
  // angle the shaft turns in the delay varies with the speed: by 10 % of that angle for a
  // speed 10 % off the mean, 0.1 deg of shaft for the 104 us of a 10 kHz record at 500 rad/s)
  opt.record_delay_s *= fr;
  opt.record_filter.reset();  // its group delays are in seconds (read by the methods refused here)
  // the resampled record's own shaft angle (the given one indexes the original samples)
  std::vector<double> angle;
  if (opt.shaft_angle) {
    angle.resize(a.x.size());
    for (std::size_t i = 0; i < angle.size(); ++i)
      angle[i] = r.theta0 + kTwoPi * static_cast<double>(i) / spr;
    opt.shaft_angle = &angle;
  }
  opt.band.lo /= fr;
  opt.band.hi /= fr;
  for (double &m : opt.mains_hz) m /= fr;  // the supply's lines, in orders
  Diagnosis d = diagnose(a, opt);
  // back to Hz at the mean speed
  d.frequency_hz *= fr;
  d.shaft_hz_estimated *= fr;  // in orders: 1 is the mean shaft speed
  d.shaft_hz_used *= fr;
  d.kinematics = defect_frequencies(opt.geometry, fr);
  d.band.lo *= fr;
  d.band.hi *= fr;
  for (Evidence &e : d.evidence) {
    e.expected_hz *= fr;
    e.frequency_hz *= fr;
  }
  if (opt.other) d.other_kinematics = defect_frequencies(*opt.other, fr);
  for (auto *fams : {&d.families, &d.other_families})
    for (FamilyScore &f : *fams) {
      f.nominal_hz *= fr;
      f.frequency_hz *= fr;
      for (Evidence &e : f.evidence) {
        e.expected_hz *= fr;
        e.frequency_hz *= fr;
      }
    }
  d.size.pulse_width_s /= fr;  // revolutions -> seconds at the mean speed
  return d;
}

}  // namespace ohmdem::post
