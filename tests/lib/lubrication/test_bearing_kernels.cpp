// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricated bearing's two kernels (bearing_kernels.h): the lanes kernel gives the plain
// kernel's bits for the entrainment speeds, the films of both races and the series of a ball's
// two contacts (the contract that lets the bearing use either); the speeds against the rolling
// kinematics; the kernels' names.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "lubrication/bearing_kernels.h"
#include "race_cases.h"

namespace ohmdem::lubrication {
namespace {

bool same_bits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Pure rolling of a ball between an inner ring turning at w_i and a fixed outer ring (radii ri,
// ro): the cage turns at w_i ri / (2 rp) and the ball spins at -w_c rp / rb, so the entrainment
// speed is (w_i - w_c) ri at the inner contact and w_c ro at the outer one (Harris; both
// surfaces' mean velocity relative to the orbiting contact point).
TEST(BearingKernels, SpeedsOfPureRollingAreTheKinematics)
{
  const double ri = 0.024, ro = 0.0366, rb = (ro - ri) / 2, rp = (ro + ri) / 2, wi = 500;
  const double wc = wi * ri / (2 * rp);
  for (double phase : {0.0, 0.7, 2.9, -1.3}) {
    const double c = std::cos(phase), s = std::sin(phase);
    const double x[3] = {rp * c, rp * s, 0}, v[3] = {-wc * rp * s, wc * rp * c, 0};
    const BallMotion ball = {x, v, -wc * rp / rb, {ro * c, ri * c}, {ro * s, ri * s}};
    const RaceFrame races[2] = {{0, 0, 0, 0, 0}, {0, 0, wi, 0, 0}};  // side 0 outer, 1 inner
    for (const auto &speed : {PlainKernel::speeds(ball, races), LanesKernel::speeds(ball, races)}) {
      EXPECT_NEAR(speed[0], wc * ro, 1e-12 * wc * ro) << phase;
      EXPECT_NEAR(speed[1], (wi - wc) * ri, 1e-12 * wi * ri) << phase;
    }
  }
}

TEST(BearingKernels, LanesSpeedsAreThePlainOnesBitForBit)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int differ = 0;
  for (int n = 0; n < 20000; ++n) {
    const double rp = 0.03 * (1 + 0.1 * u(rng)), phase = 3.2 * u(rng);
    const double x[3] = {rp * std::cos(phase) + 1e-5 * u(rng), rp * std::sin(phase), 0};
    const double v[3] = {10 * u(rng), 10 * u(rng), 0};
    BallMotion ball = {x, v, 2000 * u(rng), {}, {}};
    for (int s = 0; s < 2; ++s) {
      const double r = s == 0 ? 0.0366 : 0.024;
      ball.px[s] = r * std::cos(phase) + 1e-6 * u(rng);
      ball.py[s] = r * std::sin(phase) + 1e-6 * u(rng);
    }
    RaceFrame races[2];
    for (RaceFrame &f : races) f = {1e-4 * u(rng), 1e-4 * u(rng), 600 * u(rng), u(rng), u(rng)};
    if (n % 5 == 0) races[0] = RaceFrame{};  // a fixed ring
    const auto a = PlainKernel::speeds(ball, races), b = LanesKernel::speeds(ball, races);
    differ += !same_bits(a[0], b[0]) + !same_bits(a[1], b[1]);
  }
  EXPECT_EQ(differ, 0);
}

TEST(BearingKernels, LanesSeriesIsThePlainOneBitForBit)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::complex<double>> ys = {{0, 0}, {0, 1e-9}, {1e-3, 0}, {-0.0, 0.0}};
  for (int n = 0; n < 4000; ++n)
    ys.emplace_back(std::ldexp(u(rng), static_cast<int>(40 * u(rng))),
                    std::ldexp(u(rng), static_cast<int>(40 * u(rng))));
  int differ = 0;
  for (std::size_t i = 0; i < ys.size(); ++i)
    for (std::size_t j = i % 7; j < ys.size(); j += 97) {
      const std::complex<double> a = PlainKernel::series(ys[i], ys[j]);
      const std::complex<double> b = LanesKernel::series(ys[i], ys[j]);
      differ += !same_bits(a.real(), b.real()) + !same_bits(a.imag(), b.imag());
    }
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(PlainKernel::series({0, 0}, {0, 0}), std::complex<double>(0, 0));
}

// Both races' films, every batch size pair of a bearing up to 13 balls: the records and each
// race's smallest film and lambda the same bits.
TEST(BearingKernels, LanesFilmsAreThePlainOnesBitForBit)
{
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const RaceAdmittance a(test::race(3, 1e-3)), b(test::race(4, 1e-5));
  int differ = 0;
  for (std::size_t na = 0; na <= 13; ++na)
    for (std::size_t nb = 0; nb <= 13; ++nb) {
      ContactBatch ia, ib;
      for (std::size_t k = 0; k < na; ++k)
        ia.add(5 + 500 * u(rng), 0.2 + 20 * u(rng), u(rng) < 0.3 ? 0.0 : 1e3 * u(rng),
               u(rng) < 0.2 ? 1e-6 * u(rng) : 0.0);
      for (std::size_t k = 0; k < nb; ++k)
        ib.add(5 + 500 * u(rng), 0.2 + 20 * u(rng), 1e3 * u(rng), 0.0);
      std::vector<ContactAdmittance> pa(na), pb(nb), la(na), lb(nb);
      const RaceMinima mp = PlainKernel::contacts(a, ia, pa.data(), b, ib, pb.data());
      const RaceMinima ml = LanesKernel::contacts(a, ia, la.data(), b, ib, lb.data());
      for (std::size_t k = 0; k < na; ++k)
        differ += std::memcmp(&pa[k], &la[k], sizeof(ContactAdmittance)) != 0;
      for (std::size_t k = 0; k < nb; ++k)
        differ += std::memcmp(&pb[k], &lb[k], sizeof(ContactAdmittance)) != 0;
      for (int r = 0; r < 2; ++r)
        differ += !same_bits(mp[r].minimum, ml[r].minimum) + !same_bits(mp[r].lambda, ml[r].lambda);
    }
  EXPECT_EQ(differ, 0);
}

TEST(BearingKernels, KernelsByName)
{
  BearingKernel k = BearingKernel::lanes;
  EXPECT_TRUE(bearing_kernel_named("plain", k));
  EXPECT_EQ(k, BearingKernel::plain);
  EXPECT_TRUE(bearing_kernel_named("lanes", k));
  EXPECT_EQ(k, BearingKernel::lanes);
  EXPECT_FALSE(bearing_kernel_named("simd", k));
  EXPECT_STREQ(bearing_kernel_name(BearingKernel::plain), "plain");
  EXPECT_STREQ(bearing_kernel_name(BearingKernel::lanes), "lanes");
}

}  // namespace
}  // namespace ohmdem::lubrication
