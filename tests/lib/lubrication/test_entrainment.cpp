// SPDX-License-Identifier: GPL-2.0-or-later
// The entrainment speed (src_fix/lib/lubrication/entrainment.h): pure rolling against its
// closed form, and EntrainmentBatch::speeds (four per operation) against entrainment_speed()
// bit for bit, whatever the contact's lane and batch, in both compiled forms (SSE2, AVX2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "lubrication/entrainment.h"

using namespace ohmdem::lubrication;

namespace {

bool same_bits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// A ball of radius r rolling without slip on the inner ring (R, w_i) inside a fixed outer ring,
// at angle phi: the cage's speed and the ball's spin (lab frame) from the two no-slip
// conditions, w_c (R + r) - r w_b = w_i R at the inner ring and w_c (R + r) + r w_b = 0 at the
// outer one.
struct Rolling {
  double R = 0.024, r = 0.0063, w_i = 500.0, phi = 0.7;
  double w_c() const { return w_i * R / (2.0 * (R + r)); }
  double w_b() const { return -w_i * R / (2.0 * r); }
  BallAtContact inner_contact() const
  {
    const double d = R + r, ex = std::cos(phi), ey = std::sin(phi), wc = w_c();
    return {d * ex, d * ey, -wc * d * ey, wc * d * ex, w_b(), R * ex, R * ey};
  }
};

}  // namespace

// Pure rolling on a fixed outer ring: (omega_i - omega_cage) R_i at the inner contact (the
// rolling speed relative to the contact point, which moves with the cage).
TEST(Entrainment, PureRollingIsTheRelativeSurfaceSpeed)
{
  const Rolling b;
  RaceMotion inner;
  inner.w = b.w_i;
  const double u = entrainment_speed(b.inner_contact(), inner);
  EXPECT_NEAR(u / ((b.w_i - b.w_c()) * b.R), 1.0, 1e-12);
}

// Random balls and rings, batches of 1 to 13: every speed the scalar function's bits.
TEST(Entrainment, BatchIsTheScalarBitForBit)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int speeds = 0, differ = 0;
  EntrainmentBatch batch;  // reused: its arrays grow and keep their size, as the bearing's
  for (int n = 0; n < 2000; ++n) {
    RaceMotion m{1e-4 * u(rng), 1e-4 * u(rng), 500.0 * u(rng), 1e-2 * u(rng), 1e-2 * u(rng)};
    std::vector<BallAtContact> balls(1 + n % 13);
    batch.clear();
    for (BallAtContact &b : balls) {
      const double phi = 3.2 * u(rng), d = 0.03 + 1e-3 * u(rng);
      b = {d * std::cos(phi), d * std::sin(phi), 5.0 * u(rng), 5.0 * u(rng), 2000.0 * u(rng),
           (d - 0.0063) * std::cos(phi + 1e-3 * u(rng)), (d - 0.0063) * std::sin(phi)};
      batch.add(b);
    }
    for (const bool sse2 : {false, true}) {
      std::vector<double> out(balls.size());
      batch.speeds(m, out.data(), sse2);
      for (std::size_t k = 0; k < balls.size(); ++k) {
        differ += !same_bits(out[k], entrainment_speed(balls[k], m));
        ++speeds;
      }
    }
  }
  EXPECT_EQ(differ, 0) << "of " << speeds;
  EXPECT_GT(speeds, 20000);
}

// One contact in every lane of batches of 1 to 9 among other contacts: the same bits.
TEST(Entrainment, ASpeedDoesNotDependOnItsLaneOrBatch)
{
  const Rolling roll;
  const BallAtContact b = roll.inner_contact();
  RaceMotion m;
  m.w = roll.w_i;
  const double alone = entrainment_speed(b, m);
  BallAtContact other = b;
  other.vx += 1.0;
  for (std::size_t size = 1; size <= 9; ++size)
    for (std::size_t at = 0; at < size; ++at) {
      EntrainmentBatch batch;
      for (std::size_t k = 0; k < size; ++k) batch.add(k == at ? b : other);
      std::vector<double> out(size);
      batch.speeds(m, out.data());
      EXPECT_TRUE(same_bits(out[at], alone)) << "size " << size << " lane " << at;
      EXPECT_TRUE(same_bits(batch.at(at).wz, b.wz));
    }
}
