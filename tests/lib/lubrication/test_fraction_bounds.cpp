// SPDX-License-Identifier: GPL-2.0-or-later
// When the metallic fraction is not computed (src_fix/lib/lubrication/fraction_bounds.h): the
// bound's exponential is skipped only where the bound would fail its test, so the decision,
// and every bit of a contact's record, is what it would be with the bound computed; and the
// batched lanes (race_lanes.h, the same operations) decide as the scalar code across the band
// where the bounds decide.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "lubrication/fraction_bounds.h"
#include "lubrication/race_admittance.h"
#include "race_cases.h"

using namespace ohmdem::lubrication;
namespace fb = ohmdem::lubrication::fraction_bounds;

// x over (5.5, 27) (evenly, and just past each step of k = floor(x^2 / ln 2), where the lower
// bound 2^-(k+2) is loosest), with g_dry / leak over 60 decades and either one 0.
TEST(FractionBounds, ABoundThatCannotPassFailsItsTest)
{
  std::vector<double> xs;
  for (int i = 0; i <= 20000; ++i) xs.push_back(5.5 + 21.5 * i / 20000.0);
  for (int k = 44; k < 1010; ++k) xs.push_back(std::sqrt((k + 1e-9) * std::log(2.0)));
  std::vector<std::pair<double, double>> conductances = {{0.0, 1e-14}, {1.0, 0.0}, {0.0, 0.0}};
  for (int d = -30; d <= 30; ++d) conductances.push_back({std::pow(10.0, d) * 1e-14, 1e-14});
  long skipped = 0, failed = 0, passed = 0;
  for (const double x : xs) {
    const double k = fb::exponent(x);
    for (const auto &[g_dry, leak] : conductances) {
      const bool pass = fb::negligible(fb::bound(x), g_dry, leak);
      passed += pass;
      failed += !pass;
      if (!fb::cannot_pass(x, k, g_dry, leak)) continue;
      ++skipped;
      EXPECT_FALSE(pass) << "x " << x << " g_dry " << g_dry << " leak " << leak;
    }
  }
  std::printf("%ld cases: the bound passes %ld, fails %ld, of which %ld skipped\n", passed + failed,
              passed, failed, skipped);
  // The skip takes most failures (it misses those within about a factor 4 of passing).
  EXPECT_GT(passed, 100000);
  EXPECT_GT(skipped, 0.9 * failed);
}

// Contacts whose x = gap / (sigma sqrt 2) sweeps (5, 12) through the pit recess, with g_dry over
// 40 decades and 0: through every compiled form, each record is contact()'s bit for bit, and
// both decisions (the fraction 0, and computed) occur in the band where the bounds decide.
TEST(FractionBounds, TheLanesDecideAsTheScalarCodeAcrossTheBand)
{
  const RaceAdmittance race(test::race(0, 1e-3));
  const double sigma = race.input().sigma;
  const ContactAdmittance plain = race.contact(320.0, 5.0, 1.0, 0.0);
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<double> fn, speed, g_dry, recess;
  for (int i = 0; i < 4000; ++i) {
    const double x = 5.0 + 7.0 * u01(rng);
    fn.push_back(320.0);
    speed.push_back(5.0);
    g_dry.push_back(u01(rng) < 0.1 ? 0.0 : std::pow(10.0, -20.0 + 40.0 * u01(rng)));
    recess.push_back(std::max(x * sigma * std::sqrt(2.0) - plain.film.minimum, 1e-9));
  }
  int zero = 0, computed = 0, differ = 0;
  for (const auto isa :
       {RaceAdmittance::Isa::best, RaceAdmittance::Isa::avx2, RaceAdmittance::Isa::sse2}) {
    for (std::size_t first = 0; first < fn.size(); first += 13) {
      ContactBatch in;
      const std::size_t n = std::min<std::size_t>(13, fn.size() - first);
      for (std::size_t i = first; i < first + n; ++i) in.add(fn[i], speed[i], g_dry[i], recess[i]);
      std::vector<ContactAdmittance> out(n);
      race.contacts(in, out.data(), isa);
      for (std::size_t l = 0; l < n; ++l) {
        const std::size_t i = first + l;
        const ContactAdmittance want = race.contact(fn[i], speed[i], g_dry[i], recess[i]);
        differ += std::memcmp(&out[l], &want, sizeof want) != 0;
        if (isa != RaceAdmittance::Isa::best) continue;
        const double x = want.gap / sigma / std::sqrt(2.0);
        if (x > 6.0 && x < 9.0 && g_dry[i] > 0.0) (want.metallic == 0.0 ? zero : computed) += 1;
      }
    }
  }
  std::printf("Isa::best %s: %d records differ; in x 6-9: fraction 0 in %d, computed in %d\n",
              RaceAdmittance::best_isa(), differ, zero, computed);
  EXPECT_EQ(differ, 0);
  EXPECT_GT(zero, 300);
  EXPECT_GT(computed, 300);
}
