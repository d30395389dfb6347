// SPDX-License-Identifier: GPL-2.0-or-later
// RaceAdmittance::contacts (src_fix/lib/lubrication/race_admittance_batch.cpp), the batched
// form the bearing evaluates at every step: each contact's record must be RaceAdmittance::contact's
// bit for bit (the scalar path, itself held to the budget against contact_admittance() by
// test_race_admittance.cpp), whatever its lane, its batch's size and its neighbours, in every
// compiled form (SSE2, AVX2, AVX-512: the last two where the CPU has them); and within the
// accuracy budget of doc/methods/lubricated_contact.md "Speed" (1e-10 relative on h, C and G; held
// here to 1e-12) against contact_admittance(), the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include "lubrication/contact_admittance.h"
#include "lubrication/race_admittance.h"
#include "race_cases.h"

using namespace ohmdem::lubrication;
using namespace ohmdem::lubrication::test;

namespace {

struct Case {
  double fn, speed, g_dry, recess;
};

// Nine doubles, no padding: the record compared in all its bits.
bool same_bits(const ContactAdmittance &a, const ContactAdmittance &b)
{
  static_assert(sizeof(ContactAdmittance) == 9 * sizeof(double), "a record is nine doubles");
  return std::memcmp(&a, &b, sizeof a) == 0;
}

std::vector<ContactAdmittance> batched(const RaceAdmittance &race, const std::vector<Case> &cases,
                                       RaceAdmittance::Isa isa = RaceAdmittance::Isa::best)
{
  ContactBatch in;
  for (const Case &c : cases) in.add(c.fn, c.speed, c.g_dry, c.recess);
  std::vector<ContactAdmittance> out(cases.size());
  race.contacts(in, out.data(), isa);
  return out;
}

// The inputs where the scalar code branches, each in a batch with ordinary contacts.
std::vector<Case> edge_cases()
{
  return {
      {320.0, 5.0, 1.0, 0.0},     // ordinary: lambda ~10, erfc's bounds
      {320.0, 0.05, 1.0, 0.0},    // lambda in erfc's range (x 0.5 to 6)
      {320.0, 1e-6, 1.0, 0.0},    // lambda << 1: erfc below x = 0.5 (the scalar lane)
      {320.0, 0.0, 1.0, 0.0},     // no entrainment: the dry contact, f = 1
      {320.0, 0.0, 1.0, 2e-7},    // no entrainment over a pit
      {320.0, 5.0, 0.0, 0.0},     // a defect zone: no metal
      {320.0, 5.0, 1.0, 3e-7},    // over a pit, x in erfc's range
      {320.0, 5.0, 1.0, 1e-5},    // over a deep pit
      {320.0, 5.0, 1e300, 1e-5},  // the bound needed beyond the exponential's range
      {0.0, 5.0, 1.0, 0.0},       // no force (the scalar lane: cbrt's range)
      {-1.0, 5.0, 1.0, 0.0},      // negative force (the scalar lane)
      {1e-20, 5.0, 1.0, 0.0},     // |z| >= 0.25: h_min through its own exponential
      {320.0, 1e-310, 1.0, 0.0},  // subnormal speed (the scalar lane: log's range)
      {3e3, 50.0, 10.0, 0.0},     // fast and heavy
      {0.1, 1e-4, 1e-3, 0.0},     // light and slow
  };
}

}  // namespace

// 3000 races, batches of 1 to 13 contacts (the 6208 has 9 balls; a process may hold any number),
// the distributions of test_race_admittance.cpp.
TEST(RaceAdmittanceBatch, IsTheScalarBitForBitAndWithinTheBudget)
{
  std::mt19937_64 rng(2025);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto logu = [&](double lo, double hi) { return lo * std::pow(hi / lo, u01(rng)); };
  double worst[5] = {0, 0, 0, 0, 0};  // h_c, h_min, c_hertz, c_outer, g
  int contacts = 0, differ = 0, erfc_range = 0, recessed = 0, beyond = 0;
  for (int n = 0; n < 3000; ++n) {
    const RaceInput r = race(n, logu(2e-4, 5e-3));
    const RaceAdmittance fast(r);
    std::vector<Case> cases(1 + n % 13);
    for (Case &c : cases) {
      c.fn = logu(0.1, 3e3);
      c.speed = u01(rng) < 0.02 ? 0.0 : logu(1e-4, 50.0);
      c.g_dry = u01(rng) < 0.15 ? 0.0 : logu(1e-3, 10.0);
      c.recess = u01(rng) < 0.33 ? logu(1e-8, 1e-5) : 0.0;
    }
    for (const auto isa :
         {RaceAdmittance::Isa::best, RaceAdmittance::Isa::avx2, RaceAdmittance::Isa::sse2}) {
      const std::vector<ContactAdmittance> out = batched(fast, cases, isa);
      // The bearing's call (this race, no other) also gives the records' smallest films.
      ContactBatch in;
      for (const Case &c : cases) in.add(c.fn, c.speed, c.g_dry, c.recess);
      std::vector<ContactAdmittance> both(cases.size());
      const RaceAdmittance::Minima minima =
          RaceAdmittance::contacts(fast, in, both.data(), fast, ContactBatch{}, nullptr, isa)[0];
      RaceAdmittance::Minima want;
      for (const ContactAdmittance &a : out) {
        want.minimum = std::min(want.minimum, a.film.minimum);
        want.lambda = std::min(want.lambda, a.lambda);
      }
      differ += std::memcmp(&minima.minimum, &want.minimum, sizeof(double)) != 0;
      differ += std::memcmp(&minima.lambda, &want.lambda, sizeof(double)) != 0;
      for (std::size_t k = 0; k < cases.size(); ++k) {
        const Case &c = cases[k];
        differ += !same_bits(out[k], fast.contact(c.fn, c.speed, c.g_dry, c.recess));
        differ += !same_bits(both[k], out[k]);
        if (isa != RaceAdmittance::Isa::best) continue;
        ++contacts;
        const ContactAdmittance &a = out[k];
        const ContactInput in = input(r, c.fn, c.speed, c.g_dry, c.recess);
        const ContactAdmittance b = contact_admittance(in);
        worst[0] = std::fmax(worst[0], rel(a.film.central, b.film.central));
        worst[1] = std::fmax(worst[1], rel(a.film.minimum, b.film.minimum));
        worst[2] = std::fmax(worst[2], rel(a.c_hertz, b.c_hertz));
        worst[3] = std::fmax(worst[3], rel(a.c_outer, b.c_outer));
        worst[4] = std::fmax(worst[4], rel(a.g, b.g));
        const double x = a.gap / (r.sigma * std::sqrt(2.0));
        erfc_range += x > 0.5 && x < 6.0;
        recessed += c.recess > 0.0;
        beyond += !(r.r_wet > in.a && r.r_wet > in.b);
      }
    }
  }
  std::printf(
      "%d contacts (Isa::best: %s): %d records differ from the scalar path; worst relative "
      "differences against "
      "contact_admittance: h_c %.1e, h_min %.1e, C_hertz %.1e, C_outer %.1e, G %.1e; erfc's "
      "range in %d, over pits %d, ellipses past the wetted circle %d\n",
      contacts, RaceAdmittance::best_isa(), differ, worst[0], worst[1], worst[2], worst[3],
      worst[4], erfc_range, recessed, beyond);
  EXPECT_EQ(differ, 0);
  for (double w : worst) EXPECT_LT(w, 1e-12);
  EXPECT_GT(contacts, 20000);
  EXPECT_GT(erfc_range, 1000);
  EXPECT_GT(recessed, 5000);
  EXPECT_GT(beyond, 100);
}

// Every edge case in every lane of batches of 1 to 17 among other contacts (padding included;
// AVX-512's groups of eight and the four-lane ones after them): the same bits as alone and as
// the scalar path; never NaN for a loaded contact.
TEST(RaceAdmittanceBatch, AContactsRecordDoesNotDependOnItsLaneOrBatch)
{
  const std::vector<Case> edge = edge_cases();
  for (const double r_wet : {1e-3, 1e-5}) {  // 1e-5: the wetted circle inside the ellipse
    const RaceInput r = race(0, r_wet);
    const RaceAdmittance fast(r);
    for (std::size_t e = 0; e < edge.size(); ++e) {
      const Case &c = edge[e];
      const ContactAdmittance scalar = fast.contact(c.fn, c.speed, c.g_dry, c.recess);
      if (c.fn > 0.0) {
        EXPECT_FALSE(std::isnan(scalar.g) || std::isnan(scalar.capacitance())) << "case " << e;
      }
      for (std::size_t size = 1; size <= 17; ++size) {
        for (std::size_t lane = 0; lane < size; ++lane) {
          std::vector<Case> cases(size);
          for (std::size_t k = 0; k < size; ++k) cases[k] = edge[(e + 1 + k) % edge.size()];
          cases[lane] = c;
          for (const auto isa :
               {RaceAdmittance::Isa::best, RaceAdmittance::Isa::avx2, RaceAdmittance::Isa::sse2}) {
            const std::vector<ContactAdmittance> out = batched(fast, cases, isa);
            EXPECT_TRUE(same_bits(out[lane], scalar))
                << "case " << e << " r_wet " << r_wet << " batch " << size << " lane " << lane;
          }
        }
      }
    }
  }
}

// A process without loaded contacts on a race.
TEST(RaceAdmittanceBatch, AnEmptyBatchWritesNothing)
{
  const RaceAdmittance fast(race(1, 1e-3));
  ContactAdmittance sentinel;
  sentinel.g = 42.0;
  fast.contacts(ContactBatch{}, &sentinel);
  EXPECT_EQ(sentinel.g, 42.0);
}

// Both races at once (the bearing's call): every record is its race's scalar record bit for bit,
// for every pair of batch sizes 0 to 13 (their last contacts sharing a group where they fit, each
// lane with its own race's constants: two races of different geometry and oil film here), the
// edge cases in the shared group's lanes included, in every compiled form.
TEST(RaceAdmittanceBatch, BothRacesAtOnceAreEachRacesScalarRecords)
{
  const std::vector<Case> edge = edge_cases();
  int shared = 0, differ = 0;
  // eps_r: the races' own (the permittivity as one fraction), above 9.5 for both (its eight
  // divisions), and one of each (never in one group)
  for (const auto &eps : {std::pair{0.0, 0.0}, std::pair{12.0, 15.0}, std::pair{0.0, 12.0}})
    for (std::size_t na = 0; na <= 13; ++na)
      for (std::size_t nb = 0; nb <= 13; ++nb)
        for (std::size_t shift = 0; shift < edge.size(); shift += 4) {
          RaceInput ra = race(3, 1e-3), rb = race(4, 1e-5);  // rb: the wetted circle inside
          if (eps.first > 0) ra.eps_r = eps.first;
          if (eps.second > 0) rb.eps_r = eps.second;
          const RaceAdmittance fa(ra), fb(rb);
          ContactBatch ia, ib;
          std::vector<Case> ca, cb;
          for (std::size_t k = 0; k < na; ++k) ca.push_back(edge[(shift + k) % edge.size()]);
          for (std::size_t k = 0; k < nb; ++k) cb.push_back(edge[(shift + 7 + k) % edge.size()]);
          for (const Case &c : ca) ia.add(c.fn, c.speed, c.g_dry, c.recess);
          for (const Case &c : cb) ib.add(c.fn, c.speed, c.g_dry, c.recess);
          shared += na % 4 && nb % 4 && na % 4 + nb % 4 <= 4 && (eps.first > 0) == (eps.second > 0);
          for (const auto isa :
               {RaceAdmittance::Isa::best, RaceAdmittance::Isa::avx2, RaceAdmittance::Isa::sse2}) {
            std::vector<ContactAdmittance> oa(na + 1), ob(nb + 1);
            oa[na].g = ob[nb].g = 42.0;  // one past the end: never written
            const auto minima = RaceAdmittance::contacts(fa, ia, oa.data(), fb, ib, ob.data(), isa);
            RaceAdmittance::Minima want[2];  // the records' smallest films, in their order
            for (std::size_t k = 0; k < na; ++k) {
              const Case &c = ca[k];
              differ += !same_bits(oa[k], fa.contact(c.fn, c.speed, c.g_dry, c.recess));
              want[0].minimum = std::min(want[0].minimum, oa[k].film.minimum);
              want[0].lambda = std::min(want[0].lambda, oa[k].lambda);
            }
            for (std::size_t k = 0; k < nb; ++k) {
              const Case &c = cb[k];
              differ += !same_bits(ob[k], fb.contact(c.fn, c.speed, c.g_dry, c.recess));
              want[1].minimum = std::min(want[1].minimum, ob[k].film.minimum);
              want[1].lambda = std::min(want[1].lambda, ob[k].lambda);
            }
            for (int r = 0; r < 2; ++r) {
              differ += std::memcmp(&minima[r].minimum, &want[r].minimum, sizeof(double)) != 0;
              differ += std::memcmp(&minima[r].lambda, &want[r].lambda, sizeof(double)) != 0;
            }
            EXPECT_EQ(oa[na].g, 42.0);
            EXPECT_EQ(ob[nb].g, 42.0);
          }
        }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(shared, 200);  // the shared group was exercised, in every form
}
