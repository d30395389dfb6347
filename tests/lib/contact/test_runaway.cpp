// SPDX-License-Identifier: GPL-2.0-or-later
// The runaway check of the ball-race contacts (src_fix/lib/contact/runaway.*): silent on sound
// states, a message with the numbers and the likely cause on runaway ones.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "contact/hertz_contact.h"
#include "contact/runaway.h"

namespace ohmdem {
namespace {

// The paper's 6208 inner contact (ball 6.3 mm in a 6.55 mm groove of a 24 mm race, steel).
HertzContact inner_6208()
{
  return HertzContact(ball_inner_race(6.3e-3, 24e-3, 6.55e-3),
                      effective_modulus(200e9, 0.3, 200e9, 0.3));
}

RaceStepState sound()
{
  RaceStepState s;
  s.time = 0.01;
  s.dt = 1e-6;
  s.max_fn = 30;
  s.sum_fn = 320;
  s.fx = 1;
  s.fy = -320;
  s.u = 2e-6;
  s.ball_radius = 6.3e-3;
  s.ball_mass = 8.17e-3;
  s.ring_mass = 0.15;
  s.ring_damping = 6000;
  s.balls = 13;
  s.reference_fn = 25;
  return s;
}

bool has(const std::string &s, const std::string &part)
{
  return s.find(part) != std::string::npos;
}

TEST(Runaway, CriticalStepIsHertzStiffness)
{
  // k = dQ/ddelta = 1.5 K delta^0.5 with delta = (Q/K)^(2/3), i.e. k = 1.5 K^(2/3) Q^(1/3)
  const HertzContact h = inner_6208();
  const double K = h.stiffness_constant(), Q = 25, m = 8.17e-3;
  const double k = 1.5 * std::pow(K, 2.0 / 3.0) * std::cbrt(Q);
  EXPECT_NEAR(hertz_critical_step(h, m, Q), std::sqrt(m / k), 1e-12 * std::sqrt(m / k));
  EXPECT_EQ(hertz_critical_step(h, m, 0), 0.0);
}

TEST(Runaway, SoundStatesPass)
{
  const HertzContact h = inner_6208();
  EXPECT_EQ(race_runaway(h, sound()), "");
  RaceStepState s = sound();
  s.max_fn = s.sum_fn = 0;  // no contact at all is not a runaway
  s.balls = 0;
  EXPECT_EQ(race_runaway(h, s), "");
  // just inside the approach limit: Q = K (0.0199 rb)^1.5
  s = sound();
  s.max_fn = h.stiffness_constant() * std::pow(0.0199 * s.ball_radius, 1.5);
  EXPECT_EQ(race_runaway(h, s), "");
}

TEST(Runaway, NonFiniteStateStops)
{
  const HertzContact h = inner_6208();
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    RaceStepState s = sound();
    s.cy = bad;
    const std::string why = race_runaway(h, s);
    EXPECT_TRUE(has(why, "no longer a finite number")) << why;
    EXPECT_TRUE(has(why, "t = 0.01 s")) << why;
  }
}

TEST(Runaway, DeepApproachNamesTheStepAgainstTheCriticalSteps)
{
  const HertzContact h = inner_6208();
  RaceStepState s = sound();
  s.dt = 2e-5;
  s.max_fn = h.stiffness_constant() * std::pow(0.03 * s.ball_radius, 1.5);
  const std::string why = race_runaway(h, s);
  EXPECT_TRUE(has(why, "0.03 of the ball radius (limit 0.02")) << why;
  EXPECT_TRUE(has(why, "dt = 2e-05 s")) << why;
  EXPECT_TRUE(has(why, "sqrt(m/k)")) << why;
  EXPECT_TRUE(has(why, "sqrt(M/(n k))")) << why;
  EXPECT_TRUE(has(why, "2M/C = 5e-05 s")) << why;  // 2 x 0.15 kg / 6000 N s/m
  s.ring_mass = 0;                                 // a held ring: only the ball's step
  EXPECT_FALSE(has(race_runaway(h, s), "sqrt(M/(n k))"));
}

// The likely cause is the stiffest critical step, named first: the ring's viscous kick 2M/C
// or a light cage, not always the ball's contact step.
TEST(Runaway, StiffestCauseNamedFirst)
{
  const HertzContact h = inner_6208();
  RaceStepState s = sound();
  s.max_fn = h.stiffness_constant() * std::pow(0.03 * s.ball_radius, 1.5);
  auto cause = [&h](const RaceStepState &st) {
    const std::string why = race_runaway(h, st);
    return why.substr(why.find("the stiffest critical step, ") + 28, 40);
  };
  s.dt = 2e-5;
  EXPECT_TRUE(has(cause(s), "a ball on its contact sqrt(m/k)")) << cause(s);
  s.dt = 1e-6;
  s.ring_damping = 1e9;  // 2M/C = 0.3 ns
  EXPECT_TRUE(has(cause(s), "the ring's damping step 2M/C")) << cause(s);
  EXPECT_TRUE(has(race_runaway(h, s), "check the ring's damping")) << race_runaway(h, s);
  s.ring_damping = 6000;
  s.cage_step = 3.6e-8;  // a cage of 1e-9 kg on a ball
  s.cage_mass = 1e-9;
  EXPECT_TRUE(has(cause(s), "the cage on a ball sqrt(mu/k)")) << cause(s);
  EXPECT_TRUE(has(race_runaway(h, s), "(cage mass 1e-09 kg)")) << race_runaway(h, s);
  EXPECT_TRUE(has(race_runaway(h, s), "check the cage's mass")) << race_runaway(h, s);
}

TEST(Runaway, RingThatLeftTheBallsStops)
{
  const HertzContact h = inner_6208();
  RaceStepState s = sound();
  s.cx = 0.6 * s.ball_radius;
  EXPECT_TRUE(has(race_runaway(h, s), "it has left the balls"));
  s = sound();
  s.u = -0.6 * s.ball_radius;
  EXPECT_TRUE(has(race_runaway(h, s), "it has left the balls"));
}

}  // namespace
}  // namespace ohmdem
