// SPDX-License-Identifier: GPL-2.0-or-later
#include "contact/runaway.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace ohmdem {

double hertz_critical_step(const HertzContact &h, double mass, double fn)
{
  const double k = h.normal_stiffness(h.approach(fn));
  return k > 0 && mass > 0 ? std::sqrt(mass / k) : 0.0;
}

namespace {

bool finite(const RaceStepState &s)
{
  for (double v : {s.max_fn, s.sum_fn, s.fx, s.fy, s.torque, s.u, s.cx, s.cy})
    if (!std::isfinite(v)) return false;
  return true;
}

// What the step is against: each body's critical step; the smallest is the likely cause.
std::string likely_cause(const HertzContact &h, const RaceStepState &s)
{
  struct Step {
    double seconds;
    std::string text, check;
  };
  std::vector<Step> steps;
  const double fn = s.reference_fn > 0 ? s.reference_fn : 1.0;
  auto text = [](double x) {
    std::ostringstream o;
    o.precision(3);
    o << x;
    return o.str();
  };
  const double tb = hertz_critical_step(h, s.ball_mass, fn);
  if (tb > 0)
    steps.push_back({tb,
                     "a ball on its contact sqrt(m/k) = " + text(tb) + " s (m = " +
                         text(s.ball_mass) + " kg, k = dQ/ddelta at " + text(fn) + " N)",
                     "the ball's mass (its density and diameter)"});
  if (s.ring_mass > 0) {
    const int n = std::max(s.balls, 1);
    const double tr = hertz_critical_step(h, s.ring_mass / n, fn);
    if (tr > 0)
      steps.push_back({tr,
                       "the ring on its " + std::to_string(n) + " contacts sqrt(M/(n k)) = " +
                           text(tr) + " s (M = " + text(s.ring_mass) + " kg)",
                       "the ring's mass (fix bearing/race keyword 'mass')"});
    // an explicit viscous kick overshoots when dt C / M > 2
    if (s.ring_damping > 0)
      steps.push_back({2 * s.ring_mass / s.ring_damping,
                       "the ring's damping step 2M/C = " + text(2 * s.ring_mass / s.ring_damping) +
                           " s (M = " + text(s.ring_mass) + " kg, C = " + text(s.ring_damping) +
                           " N s/m)",
                       "the ring's damping (fix bearing/race keyword 'damp')"});
  }
  if (s.cage_step > 0)
    steps.push_back({s.cage_step,
                     "the cage on a ball sqrt(mu/k) = " + text(s.cage_step) + " s (cage mass " +
                         text(s.cage_mass) + " kg)",
                     "the cage's mass (fix bearing/cage keyword 'mass')"});
  std::ostringstream o;
  o.precision(3);
  if (steps.empty()) {
    o << "; likely cause: the time step dt = " << s.dt << " s: check the masses and the damping";
    return o.str();
  }
  std::stable_sort(steps.begin(), steps.end(),
                   [](const Step &a, const Step &b) { return a.seconds < b.seconds; });
  o << "; likely cause: the time step dt = " << s.dt << " s against the stiffest critical step, "
    << steps.front().text;
  for (std::size_t k = 1; k < steps.size(); ++k)
    o << (k == 1 ? " (then " : ", ") << steps[k].text << (k + 1 == steps.size() ? ")" : "");
  o << ": take dt well below it (a tenth of it), or check " << steps.front().check;
  return o.str();
}

}  // namespace

std::string race_runaway(const HertzContact &h, const RaceStepState &s)
{
  // the tests first: this runs at every step, the message almost never
  const bool is_finite = finite(s);
  const double delta = is_finite ? h.approach(s.max_fn) : 0.0;
  const double offset = is_finite ? std::max(std::hypot(s.cx, s.cy), std::fabs(s.u)) : 0.0;
  const bool too_deep = delta > kRunawayApproachFraction * s.ball_radius;
  const bool too_far = offset > kRunawayOffsetFraction * s.ball_radius;
  if (is_finite && !too_deep && !too_far) return "";

  std::ostringstream o;
  o.precision(6);
  o << "the ball-race contacts ran away at t = " << s.time << " s: ";
  if (!is_finite)
    o << "a force or the ring's position is no longer a finite number (sum of normal forces "
      << s.sum_fn << " N, ring offset " << s.cx << ", " << s.cy << " m, interference " << s.u
      << " m)";
  else if (too_deep)
    o << "a normal force of " << s.max_fn << " N means an approach of " << delta << " m, "
      << delta / s.ball_radius << " of the ball radius (limit " << kRunawayApproachFraction
      << ": far beyond the elastic range)";
  else
    o << "the ring moved by " << offset << " m, " << offset / s.ball_radius
      << " of the ball radius (limit " << kRunawayOffsetFraction << "): it has left the balls";
  return o.str() + likely_cause(h, s);
}

}  // namespace ohmdem
