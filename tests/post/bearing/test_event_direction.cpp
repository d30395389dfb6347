// SPDX-License-Identifier: GPL-2.0-or-later
// An outer defect's angle from a two-axis accelerometer (post/bearing/event_direction.h) on
// synthetic records: at every defect pass a ring r = A exp(-s/tau) sin(w s) along the direction
// theta (first axis cos(theta) r, second sin(theta) r: the reference is the construction),
// over a steady tone on the first axis only (as the ball-pass ripple along the load) that the
// background must remove, with noise of the same level on each axis, drawn independently,
// through dsp/acquire's anti-alias filter.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "bearing/diagnose.h"
#include "bearing/event_direction.h"
#include "bearing/race_sizing.h"
#include "dsp/acquire.h"
#include "test_constants.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

constexpr double kF = 200, kFb = 1000, kTau = 300e-6;  // passes (Hz), ring (Hz), its decay (s)

struct TwoAxes {
  std::vector<double> first, second;
};

// 0.3 s (60 passes, from t = -0.3 / kF), 1 MHz, acquired at `rate` (lowpass 0.4 x rate).
TwoAxes record(double theta_deg, double a, double rate, double noise)
{
  const double fs = 1e6, th = theta_deg * kPi / 180;
  const auto n = static_cast<std::size_t>(0.3 * fs);
  Signal x, y;
  x.rate = y.rate = fs;
  x.x.resize(n);
  y.x.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs, s = std::fmod(t * kF + 0.3, 1.0) / kF;
    const double ring = a * std::exp(-s / kTau) * std::sin(2 * kPi * kFb * s);
    x.x[i] = 0.05 * std::sin(2 * kPi * 1234 * t) + std::cos(th) * ring;
    y.x[i] = std::sin(th) * ring;
  }
  AcquireSettings acq;
  acq.lowpass = 0.4 * rate;
  acq.rate = rate;
  acq.noise_rms = noise;
  acq.seed = 1;
  TwoAxes out;
  out.first = acquire(x, acq).signal.x;
  acq.seed = 2;  // each axis its own noise
  out.second = acquire(y, acq).signal.x;
  return out;
}

double axis_error(double a, double b)
{
  double d = std::fmod(a - b, 180.0);
  if (d > 90) d -= 180;
  if (d <= -90) d += 180;
  return d;
}

TEST(EventDirection, DirectionOfTheEventsAtEveryRate)
{
  for (double rate : {1e4, 2e4, 5e4})
    for (double theta : {-60.0, -25.0, 0.0, 10.0, 40.0, 75.0, 89.0, -89.0}) {
      const TwoAxes r = record(theta, 2.0, rate, 0.1);
      const EventDirection d = event_direction(r.first, r.second, rate, kF, {});
      ASSERT_TRUE(d.valid) << rate << " " << theta << ": " << d.note;
      EXPECT_GE(d.passes, 55U);
      EXPECT_GT(d.angle_deg, -90.0);
      EXPECT_LE(d.angle_deg, 90.0);
      // no ring response here to turn the events: the noise leaves up to ~1 deg (the same
      // draws at every angle of a rate: their errors go together), within the jackknife's
      // part of the interval
      const double error = axis_error(d.angle_deg, theta);
      EXPECT_LT(std::fabs(error), 1.5) << rate << " " << theta;
      // the interval: the jackknife's spread plus the model's allowance (3 deg)
      EXPECT_GE(d.half_width_deg, 3.0);
      EXPECT_LT(d.half_width_deg, 5.0) << rate << " " << theta;
      EXPECT_LT(std::fabs(error), d.half_width_deg - 3.0) << rate << " " << theta;
      EXPECT_GT(d.events_to_background, 1.0);
    }
}

TEST(EventDirection, NoEventsNoDirection)
{
  // the tone and the noise alone: the tone lies along the first axis, and the windows, each on
  // its pass's strongest stretch, hold a few tenths more energy than the background: no event
  // stands out
  const TwoAxes r = record(30, 0.0, 2e4, 0.1);
  const EventDirection d = event_direction(r.first, r.second, 2e4, kF, {});
  EXPECT_FALSE(d.valid);
  EXPECT_TRUE(std::isnan(d.angle_deg));
  EXPECT_NE(d.note.find("not determined: no defect events stand out of the background"),
            std::string::npos)
      << d.note;
}

TEST(EventDirection, FewPassesAndBadSettings)
{
  const TwoAxes r = record(30, 2.0, 2e4, 0.1);
  const std::vector<double> a(r.first.begin(), r.first.begin() + 1000),
      b(r.second.begin(), r.second.begin() + 1000);
  const EventDirection d = event_direction(a, b, 2e4, kF, {});
  EXPECT_FALSE(d.valid);
  EXPECT_NE(d.note.find("defect passes in the record, fewer than twice the 10 groups"),
            std::string::npos)
      << d.note;
  EXPECT_NE(event_direction(r.first, r.second, 2e4, 3e3, {}).note.find("an eighth of the rate"),
            std::string::npos);
  EXPECT_THROW(event_direction(a, r.second, 2e4, kF, {}), std::invalid_argument);
  EventDirectionSettings s;
  s.groups = 2;
  EXPECT_THROW(event_direction(r.first, r.second, 2e4, kF, s), std::invalid_argument);
  s = {};
  s.model_deg = -1;
  EXPECT_THROW(event_direction(r.first, r.second, 2e4, kF, s), std::invalid_argument);
  EXPECT_THROW(event_direction(r.first, r.second, 0, kF, {}), std::invalid_argument);
}

TEST(EventDirection, PlacesAnOuterDefectUnderARadialLoadOnly)
{
  const TwoAxes r = record(-35, 2.0, 2e4, 0.1);
  Signal s, across;
  s.rate = across.rate = 2e4;
  s.x = r.first;
  across.x = r.second;
  RaceToSize outer;
  outer.defect = "outer";
  outer.f = kF;
  outer.race = true;
  DiagnoseOptions o;
  o.load = "radial";
  DefectLocation l;
  place_outer_by_event_direction(s, outer, o, l);  // no second axis: left as it is
  EXPECT_TRUE(std::isnan(l.position_deg));
  EXPECT_TRUE(l.position_reference.empty());
  o.across = &across;
  l.position_modulo_deg = 27.69;  // another method's "modulo the ball spacing" is replaced
  place_outer_by_event_direction(s, outer, o, l);
  EXPECT_NEAR(l.position_deg, -35, 1.0);
  EXPECT_LT(l.position_lo_deg, -35);
  EXPECT_GT(l.position_hi_deg, -35);
  EXPECT_EQ(l.position_reference, "load direction");
  EXPECT_TRUE(std::isnan(l.position_modulo_deg));
  EXPECT_NE(l.position_note.find("a pit beyond 90 deg from the load reads 180 deg off"),
            std::string::npos)
      << l.position_note;
  // an inner defect is the shaft angle's (pass_energy.h): left as it is
  DefectLocation inner_l;
  RaceToSize inner = outer;
  inner.defect = "inner";
  place_outer_by_event_direction(s, inner, o, inner_l);
  EXPECT_TRUE(std::isnan(inner_l.position_deg));
  // no load direction under a balanced load
  o.load = "fixed";
  DefectLocation fixed_l;
  place_outer_by_event_direction(s, outer, o, fixed_l);
  EXPECT_TRUE(std::isnan(fixed_l.position_deg));
  EXPECT_NE(fixed_l.position_note.find("only a radial load has"), std::string::npos);
}

}  // namespace
}  // namespace ohmdem::post
