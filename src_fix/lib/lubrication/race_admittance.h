// SPDX-License-Identifier: GPL-2.0-or-later
// The contacts of one race, evaluated for every ball at every step: contact_admittance() and
// idle_gap_capacitance() with everything that depends only on the race and the oil computed
// once (the Hamrock-Dowson prefactors and ellipticity factors, the Hertz ellipse at 1 N and its
// form mean, the gap integral's race terms, the permittivity's Gauss sum as one fraction), the
// inline logarithm, exponential and erfc of common/, and no erfc where the metallic fraction
// cannot change the result (below). Same equations as contact_admittance.h, within the
// accuracy budget of doc/methods/lubricated_contact.md "Speed" (1e-10 relative on h, C and G; ~1e-13
// reached, tests/lib/lubrication/test_race_admittance.cpp). Plain C++.
#ifndef OHMDEM_LUBRICATION_RACE_ADMITTANCE_H
#define OHMDEM_LUBRICATION_RACE_ADMITTANCE_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "lubrication/contact_admittance.h"

namespace ohmdem::lubrication {

// The inputs of a race's loaded contacts, one array per input (RaceAdmittance::contacts). The
// arrays keep their size between steps: one capacity test per contact.
class ContactBatch {
 public:
  std::size_t size() const { return n_; }
  void clear() { n_ = 0; }
  // Returns the contact's index in the batch.
  std::size_t add(double fn, double speed, double g_dry, double recess)
  {
    if (n_ == capacity_) grow();
    return add_reserved(fn, speed, g_dry, recess);
  }
  // Room for n contacts in all; add_reserved() then has no capacity test (the bearing's loop:
  // at most one contact per ball and race, reserved for every local atom).
  void reserve(std::size_t n)
  {
    while (capacity_ < n) grow();
  }
  std::size_t add_reserved(double fn, double speed, double g_dry, double recess)
  {
    fn_[n_] = fn;
    speed_[n_] = speed;
    g_dry_[n_] = g_dry;
    recess_[n_] = recess;
    return n_++;
  }
  const double *fn() const { return fn_.data(); }
  const double *speed() const { return speed_.data(); }
  const double *g_dry() const { return g_dry_.data(); }
  const double *recess() const { return recess_.data(); }

 private:
  void grow()
  {
    capacity_ = 2 * capacity_ + 16;
    for (std::vector<double> *v : {&fn_, &speed_, &g_dry_, &recess_}) v->resize(capacity_);
  }
  std::vector<double> fn_, speed_, g_dry_, recess_;
  std::size_t n_ = 0, capacity_ = 0;  // capacity_: the arrays' size (one load to test)
};

// A race's constants for one run.
struct RaceInput {
  double rx = 0, ry = 0;          // effective radii (m), rolling direction and across it
  double e_prime = 0;             // E' (Pa)
  double a_coef = 0, b_coef = 0;  // Hertz semi-axes at 1 N (m): a = a_coef fn^(1/3)
  double eta = 0, alpha = 0;      // oil at the temperature
  double sigma = 0, r_wet = 0, eps_r = 0, resistivity = 0;  // as in ContactInput
};

class RaceAdmittance {
 public:
  RaceAdmittance() = default;
  explicit RaceAdmittance(const RaceInput &in);
  // contact_admittance() of a contact of this race under the load fn > 0 (N) at the mean
  // entrainment speed `speed` (m/s), its Hertz ellipse a = a_coef fn^(1/3), b = b_coef fn^(1/3).
  // The metallic fraction f = erfc(x) (x = gap / (sigma sqrt 2)) is set to 0 without calling
  // erfc when erfc(x) <= e^(-x^2) / (x sqrt(pi)) (x > 0) is below both 2^-54 (then 1 - f is 1
  // exactly, so C does not change in any bit) and 1e-17 of the leakage over g_dry (then G
  // changes by less than 1e-17 relative). From x = 6 the bound is first taken from the
  // exponent bits, without the exponential (race_admittance.cpp); the decision is the same.
  // Written into c (every field): the bearing's loop fills its records in place.
  void contact(double fn, double speed, double g_dry, double recess, ContactAdmittance &c) const;
  ContactAdmittance contact(double fn, double speed, double g_dry, double recess) const
  {
    ContactAdmittance c;
    contact(fn, speed, g_dry, recess, c);
    return c;
  }
  // The batch's contacts into out[0..size), four or eight at a time
  // (race_admittance_batch.cpp): out[k] is contact(fn[k], speed[k], g_dry[k], recess[k]) bit
  // for bit, whatever its place in the batch and the batch's size. Compiled for SSE2, AVX2
  // and AVX-512 (F and DQ), the best the CPU has taken unless `isa` asks for AVX2 or SSE2 at
  // most (the tests compare all three).
  enum class Isa { best, avx2, sse2 };
  // The set Isa::best runs with on this CPU: "avx512", "avx2" or "sse2" (for logs).
  static const char *best_isa();
  void contacts(const ContactBatch &in, ContactAdmittance *out, Isa isa = Isa::best) const;
  // The smallest film.minimum and lambda of a race's records (infinity: no record), taken
  // four wide where the records are (the caller's loop need not visit them). min is exact and
  // the records hold no -0 (films >= +0), so the order of the comparisons does not matter; a
  // NaN is passed over, as std::min(smallest, x) passes it.
  struct Minima {
    double minimum = std::numeric_limits<double>::infinity();
    double lambda = std::numeric_limits<double>::infinity();
  };
  // Both races of a bearing at once: each race's contacts as contacts() gives them (the same
  // bits), its full groups of four alone, and the two races' last contacts together in one
  // group where they fit in it (a bearing of 13 balls: one group instead of two contacts by
  // the scalar code). The races' oils must be the same (their permittivity in the same form);
  // else, or where the last contacts do not fit one group, each race's as contacts().
  // Returns each race's Minima (a's, then b's).
  static std::array<Minima, 2> contacts(const RaceAdmittance &a, const ContactBatch &in_a,
                                        ContactAdmittance *out_a, const RaceAdmittance &b,
                                        const ContactBatch &in_b, ContactAdmittance *out_b,
                                        Isa isa = Isa::best);
  // idle_gap_capacitance(gap, rx, ry, r_wet, eps_r, sigma).
  double idle(double gap) const;
  const RaceInput &input() const { return in_; }

 private:
  friend struct RaceLanes;  // the batched form's lanes (race_lanes.h)
  RaceInput in_;
  double central_ = 0, minimum_ = 0;  // Hamrock-Dowson prefactor times ellipticity factor
  double ell_central_ = 0, ell_minimum_ = 0;
  double area_coef_ = 0;  // pi a b at 1 N
  // The pressure-raised permittivity: nodes t and weights w t, eps = (al + be q)/(ga + de q)
  // = eps_const_ / sum(w t) + eps_pole_ / (ga + de q); dt_ = de t.
  std::array<double, 8> t_{}, wt_{}, dt_{};
  double ga_ = 0, eps_const_ = 0, eps_pole_ = 0;
  // The gap integral (contact_admittance.cpp, gap_capacitance): 2 rx, 2 ry, r_wet^2, the
  // form means of (sqrt(2 rx), sqrt(2 ry)), and eps0 eps_r sqrt(rx ry) 2 pi.
  double p_ = 0, q_ = 0, r2_ = 0, pq_s_ = 0, pq_y_ = 1, scale_ = 0;
  // Per race rather than per contact (doc/methods/lubricated_contact.md, "Speed"): sqrt(2 rx),
  // sqrt(2 ry); sqrt(2 rx)/b and sqrt(2 ry)/a at 1 N; the Hertz ellipse's form mean over the
  // race's (s at 1 N, y); 1/sigma, 1/resistivity; the peak pressure (GPa) at 1 N; the
  // permittivity's sum as P(q)/Q(q) (coefficients from the constant term; rational_ false:
  // the eight divisions).
  double sqrt_p_ = 0, sqrt_q_ = 0, sp_coef_ = 0, sq_coef_ = 0, hertz_s_ = 0, hertz_y_ = 1;
  double inv_sigma_ = 0, inv_resistivity_ = 0, q0_coef_ = 0;
  std::array<double, 8> pc_{};
  std::array<double, 9> qc_{};
  bool rational_ = false;
  double permittivity(double q0) const;
  // The constants the batched form reads, each four times over (its vector operands: one load
  // per use rather than a broadcast), laid out as race_lanes.h's RaceConstants; set at the end
  // of the constructor by splat_constants (race_admittance_batch.cpp).
  static constexpr int kSplat = 4 * 56, kSplat8 = 8 * 56;
  alignas(32) std::array<double, kSplat> splat_{};
  alignas(64) std::array<double, kSplat8> splat8_{};  // eight times over (AVX-512's groups)
  static void splat_constants(RaceAdmittance &r);
  // This race's constants, numbered per construction (a copy keeps the number: the same
  // constants); 0 for a default one.
  std::uint64_t serial_ = 0;
  // contacts(a, ..., b, ...)'s shared group: its constants blended lane by lane (la lanes of
  // a, then b's), kept by race a for its last partner and rebuilt only when b, la or lb change
  // (~-180 instructions a step). Mutable: one caller at a time per race a.
  struct Blended {
    std::uint64_t partner = 0;
    std::size_t la = 0, lb = 0;  // la = 0: none yet
    alignas(32) std::array<double, kSplat> splat{};
  };
  mutable Blended blended_;
};

}  // namespace ohmdem::lubrication

#endif
