// SPDX-License-Identifier: GPL-2.0-or-later
// RaceAdmittance::contacts: a race's contacts four per operation (common/lanes4.h), each lane
// the same operations in the same order as RaceAdmittance::contact, so each contact's record
// is that function's bit for bit (the bench's deck gives the same numbers as the scalar path,
// with any number of processes). The scalar function's branches are masks; a lane that would
// take one of its rare branches (inputs outside the inline functions' ranges, erfc below 0.5,
// the wetted circle not holding the ellipse) is redone by the scalar code, alone. A last group
// of one contact goes to the scalar code too (cheaper than four lanes); one of two or three is
// padded with a plain contact that is computed and dropped. Both races at once: their last
// contacts share a group, each lane with its race's constants. The constants are read as
// four-lane operands kept by RaceAdmittance (one load per use instead of a broadcast). The body is
// compiled twice, for SSE2 and AVX2 (there with lanes4.h's gathers, sign masks and blends: kAvx2),
// chosen at run time: the same bits (no FMA: the file is built with -ffp-contract=off).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "common/constants.h"
#include "common/estrin.h"
#include "common/fast_exp_log.h"
#include "common/lanes4.h"
#include "lubrication/race_admittance.h"
#include "lubrication/race_lane_functions.h"

namespace ohmdem::lubrication {

namespace {

using lanes::kLanes;
using lanes::select;
using lanes::splat;
using lanes::v4d;
using lanes::v4i;
using lanes::v4u;
using race_lanes::aliasing;
using race_lanes::erfc_where;
using race_lanes::exp_small;
using race_lanes::form_mean;
using race_lanes::Forms;
using race_lanes::in_log_range;
using race_lanes::log_where;

const double kSqrtHalf = std::sqrt(0.5), kSqrtPi = std::sqrt(kPi);  // as race_admittance.cpp

}  // namespace

// RaceAdmittance's constants as the kernel's operands, four lanes each (its splat_ holds them
// in this layout). A group of one race reads its race's; a group of two races' contacts, lanes
// blended from both.
struct RaceConstants {
  v4d a_coef, b_coef, central, ell_central, minimum, ell_minimum, inv_sigma, area_coef,
      inv_resistivity, q0_coef, sigma, r_wet, p, q, r2, sp_coef, sq_coef, hertz_s, hertz_y, scale,
      eps_const, eps_pole, ga;
  v4d pc[8], qc[9], wt[8], dt[8];
};

// The records as nine doubles in a row (store_rows writes fields 0-3 and 4-7 four at a time).
static_assert(sizeof(ContactAdmittance) == 9 * sizeof(double) &&
                  offsetof(ContactAdmittance, film) == 0 &&
                  offsetof(ContactAdmittance, lambda) == 2 * sizeof(double) &&
                  offsetof(ContactAdmittance, metallic) == 3 * sizeof(double) &&
                  offsetof(ContactAdmittance, c_hertz) == 4 * sizeof(double) &&
                  offsetof(ContactAdmittance, c_outer) == 5 * sizeof(double) &&
                  offsetof(ContactAdmittance, g) == 6 * sizeof(double) &&
                  offsetof(ContactAdmittance, gap) == 7 * sizeof(double) &&
                  offsetof(ContactAdmittance, g_dry) == 8 * sizeof(double) &&
                  offsetof(Film, minimum) == sizeof(double),
              "ContactAdmittance: central, minimum, lambda, metallic, c_hertz, c_outer, g, gap, "
              "g_dry");

// What a group of four reads: the constants, each lane's race (for the scalar code's rare
// lanes) and where each lane's record goes: base[l] for one race's group (lanes null), else
// lanes[l].
struct Group {
  const RaceConstants *k;
  const RaceAdmittance *race[kLanes];
  ContactAdmittance *base;
  ContactAdmittance *const *lanes;
  ContactAdmittance &out(int l) const { return lanes ? *lanes[l] : base[l]; }
};

// Friend of RaceAdmittance: its constants.
struct RaceLanes {
  static_assert(sizeof(RaceConstants) == sizeof(double) * RaceAdmittance::kSplat,
                "RaceAdmittance::splat_ holds RaceConstants");
  static_assert(alignof(RaceConstants) <= 32, "splat_ is 32-byte aligned");

  static const RaceConstants &constants(const RaceAdmittance &r)
  {
    return *reinterpret_cast<const RaceConstants *>(r.splat_.data());
  }

  // A race's smallest film.minimum: over its full groups lane by lane (folded into one at the
  // race's end), and over the records written one by one. Its lambda is minimum / sigma, each
  // record's film.minimum * inv_sigma_ (contact() and four()): rounding is monotonic, so the
  // smallest lambda is the smallest film's, bit for bit (RaceAdmittance::contacts, at the end).
  static OHMDEM_LANES_INLINE void fold(double &minimum, const ContactAdmittance &c)
  {
    minimum = std::min(minimum, c.film.minimum);
  }
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE double fold(double minimum, v4d lanes)
  {
    const v4d pairs = lanes::min<kAvx2>(lanes, __builtin_shuffle(lanes, v4i{2, 3, 0, 1}));
    const v4d all = lanes::min<kAvx2>(pairs, __builtin_shuffle(pairs, v4i{1, 0, 3, 2}));
    return std::min(minimum, all[0]);
  }

  static OHMDEM_LANES_INLINE v4d permittivity(bool rational, const RaceConstants &k, v4d q0)
  {
    if (rational) {
      const v4d num = estrin::polynomial<8>(k.pc, q0), den = estrin::polynomial<9>(k.qc, q0);
      return k.eps_const + k.eps_pole * (num / den);
    }
    v4d sum = splat(0.0);
    for (int i = 0; i < 8; ++i) sum += k.wt[i] / (k.ga + q0 * k.dt[i]);
    return k.eps_const + k.eps_pole * sum;
  }

  // Lanes [0, m) of fn ... into the group's records; the comments are RaceAdmittance::contact's
  // steps. `rational`: the races' permittivity form (the same for every lane). Returns whether
  // the group's films went into `minima` (one race's full group, stored four wide); else the
  // caller takes them from the records.
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE bool four(const Group &grp, bool rational, v4d fn, v4d speed,
                                       v4d g_dry, v4d recess, int m, v4d *minima)
  {
    const RaceConstants &k = *grp.k;
    // A contact that does not roll (its cube root) or whose inputs leave log_fast's range: the
    // scalar code.
    const v4i moving = (speed > 0.0) & (fn > 0.0);
    const v4i odd = ~(moving & in_log_range(speed) & in_log_range(fn));
    const v4i go = ~odd;
    const v4d ls = lanes::log<kAvx2>(select<kAvx2>(go, speed, splat(1.0)));
    const v4d lw = lanes::log<kAvx2>(select<kAvx2>(go, fn, splat(1.0)));
    const v4d cb = lanes::exp<kAvx2>(lw * (1.0 / 3.0));
    const v4d a = k.a_coef * cb, b = k.b_coef * cb;
    // The films.
    const v4d central_power = lanes::exp<kAvx2>(0.67 * ls - 0.067 * lw);
    const v4d central = select<kAvx2>(go, k.central * central_power * k.ell_central, splat(0.0));
    const v4d z = 0.01 * ls - 0.006 * lw;
    const v4i near = (z < 0.25) & (z > -0.25);
    v4d power_min = central_power * exp_small(z);
    if (!lanes::all<kAvx2>(near))
      power_min =
          select<kAvx2>(near, power_min,
                        lanes::exp<kAvx2>(select<kAvx2>(near, splat(0.0), 0.68 * ls - 0.073 * lw)));
    const v4d minimum = select<kAvx2>(go, k.minimum * power_min * k.ell_minimum, splat(0.0));
    const v4d lambda = minimum * k.inv_sigma;
    const v4d gap = minimum + recess;
    const v4d area = k.area_coef * cb * cb;
    const v4d h = central + recess;
    const v4i film = (h > 0.0) & (area > 0.0);
    const v4d area_h = select<kAvx2>(film, area / select<kAvx2>(film, h, splat(1.0)), splat(0.0));
    const v4d leak = area_h * k.inv_resistivity;
    // The metallic fraction, or 0 when it cannot matter: the cheap bound from x = 6 ...
    const v4d xm = select<kAvx2>(recess > 0.0, gap * k.inv_sigma, lambda) * kSqrtHalf;
    const v4i big = xm >= 6.0;
    v4i negligible = big & 0;
    if (lanes::any<kAvx2>(big)) {
      // min(floor(v), 1000) as floor(min(v, 1000)), the floor through 2^52 (0 <= v <= 1000).
      const v4d v =
          lanes::min<kAvx2>(xm * xm * (1.4426950408889634 * (1.0 - 1e-12)), splat(1000.0));
      const v4d shifted = v + 0x1p52;
      const v4i e = ((v4i)shifted - (v4i)splat(0x1p52)) + ((shifted - 0x1p52) > v);
      const v4d cheap = 0.1 * (v4d)((v4u)(1023 - e) << 52);  // 0.1 pow2_neg(e)
      negligible = big & (cheap <= 0x1p-54) & (cheap * g_dry <= 1e-17 * leak);
    }
    // ... then the bound itself from 5.5.
    const v4i bound_lanes = ~negligible & (xm > 5.5);
    if (lanes::any<kAvx2>(bound_lanes)) {
      const v4d e = -xm * xm;
      const v4i fast = bound_lanes & (e > -708.0) & (e < 709.0);  // exp_fast's range
      v4d ex = lanes::exp<kAvx2>(select<kAvx2>(fast, e, splat(0.0)));
      if (!lanes::all<kAvx2>(fast | ~bound_lanes))
        for (int l = 0; l < kLanes; ++l)
          if (bound_lanes[l] && !fast[l]) ex[l] = exp_fast(e[l]);
      const v4d bound = ex / (xm * kSqrtPi);
      negligible |= bound_lanes & (bound <= 0x1p-54) & (bound * g_dry <= 1e-17 * leak);
    }
    const v4d metallic =
        lanes::any<kAvx2>(~negligible) ? erfc_where<kAvx2>(~negligible, xm) : splat(0.0);
    const v4d free = 1.0 - metallic;
    v4d g = metallic * g_dry;
    const v4i zone = film & (free > 0.0);
    v4d c_hertz = splat(0.0);
    if (lanes::any<kAvx2>(zone)) {
      const v4d q0 = k.q0_coef * cb;
      c_hertz =
          select<kAvx2>(zone, free * kEpsilon0 * permittivity(rational, k, q0) * area_h, c_hertz);
      g = select<kAvx2>(zone, g + free * leak, g);
    }
    // The gap's closed form while the wetted circle holds the ellipse (else the scalar code's
    // gap_capacitance).
    const v4d h0 = lanes::max<kAvx2>(central, k.sigma) + recess;
    const v4i wet = (k.r_wet > a) & (k.r_wet > b) & (a > 0.0) & (b > 0.0);
    const Forms outer = form_mean(lanes::sqrt(h0 * k.p + k.r2), lanes::sqrt(h0 * k.q + k.r2));
    const v4d inv_cb = 1.0 / cb, sp = k.sp_coef * inv_cb, sq = k.sq_coef * inv_cb;
    const Forms inner = form_mean(lanes::sqrt(h0 * sp * sp + 1.0), lanes::sqrt(h0 * sq * sq + 1.0));
    const v4d x = outer.s * k.hertz_s * inv_cb / inner.s, y = outer.y * k.hertz_y / inner.y;
    const v4d c_outer = k.scale * (2.0 * log_where<kAvx2>(wet, x) + aliasing<kAvx2>(wet, y));
    // The records, lane by lane (a full group with no odd lane and the closed form in every
    // lane: the lanes' indices are constants, so no vector goes through memory).
    if (m == kLanes && !lanes::any<kAvx2>(odd) && lanes::all<kAvx2>(wet)) {
      // Fields 0-3 and 4-7 of the four records transposed (four rows of four), the ninth alone.
      store_rows(grp, 0, central, minimum, lambda, metallic);
      store_rows(grp, 4, c_hertz, c_outer, g, gap);
#pragma GCC unroll 4
      for (int l = 0; l < kLanes; ++l) grp.out(l).g_dry = g_dry[l];
      if (!minima) return false;
      *minima = lanes::min<kAvx2>(*minima, minimum);
      return true;
    }
    for (int l = 0; l < m; ++l) {
      const RaceAdmittance &r = *grp.race[l];
      if (odd[l]) {
        r.contact(fn[l], speed[l], g_dry[l], recess[l], grp.out(l));
        continue;
      }
      const RaceInput &ri = r.in_;
      record(grp.out(l), central[l], minimum[l], lambda[l], metallic[l], c_hertz[l],
             wet[l] ? c_outer[l]
                    : gap_capacitance(GapGeometry{h0[l], ri.rx, ri.ry, a[l], b[l], ri.r_wet},
                                      ri.eps_r),
             g[l], gap[l], g_dry[l]);
    }
    return false;
  }

  // Lane l of (a, b, c, d) into the four doubles of record l from its field `first`.
  static OHMDEM_LANES_INLINE void store_rows(const Group &grp, int first, v4d a, v4d b, v4d c,
                                             v4d d)
  {
    const v4d ab_lo = __builtin_shuffle(a, b, v4i{0, 4, 2, 6});  // a0 b0 a2 b2
    const v4d ab_hi = __builtin_shuffle(a, b, v4i{1, 5, 3, 7});  // a1 b1 a3 b3
    const v4d cd_lo = __builtin_shuffle(c, d, v4i{0, 4, 2, 6});
    const v4d cd_hi = __builtin_shuffle(c, d, v4i{1, 5, 3, 7});
    const v4d rows[kLanes] = {__builtin_shuffle(ab_lo, cd_lo, v4i{0, 1, 4, 5}),
                              __builtin_shuffle(ab_hi, cd_hi, v4i{0, 1, 4, 5}),
                              __builtin_shuffle(ab_lo, cd_lo, v4i{2, 3, 6, 7}),
                              __builtin_shuffle(ab_hi, cd_hi, v4i{2, 3, 6, 7})};
#pragma GCC unroll 4
    for (int l = 0; l < kLanes; ++l)
      __builtin_memcpy(reinterpret_cast<double *>(&grp.out(l)) + first, &rows[l], sizeof rows[l]);
  }

  static OHMDEM_LANES_INLINE void record(ContactAdmittance &c, double central, double minimum,
                                         double lambda, double metallic, double c_hertz,
                                         double c_outer, double g, double gap, double g_dry)
  {
    c.film.central = central;
    c.film.minimum = minimum;
    c.lambda = lambda;
    c.metallic = metallic;
    c.c_hertz = c_hertz;
    c.c_outer = c_outer;
    c.g = g;
    c.gap = gap;
    c.g_dry = g_dry;
  }

  // One race's contacts [i, i + m) (1 < m <= 4) as a group; padding: a loaded, rolling contact
  // whose record is dropped.
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE void group_of(const RaceAdmittance &r, const ContactBatch &in,
                                           std::size_t i, int m, ContactAdmittance *out,
                                           v4d &lanes, double &records)
  {
    const Group grp{&constants(r), {&r, &r, &r, &r}, out + i, nullptr};
    v4d fn, speed, g_dry, recess;
    if (m == kLanes) {
      __builtin_memcpy(&fn, in.fn() + i, sizeof fn);
      __builtin_memcpy(&speed, in.speed() + i, sizeof speed);
      __builtin_memcpy(&g_dry, in.g_dry() + i, sizeof g_dry);
      __builtin_memcpy(&recess, in.recess() + i, sizeof recess);
    } else {
      fn = speed = splat(1.0);
      g_dry = recess = splat(0.0);
      for (int l = 0; l < m; ++l) {
        fn[l] = in.fn()[i + l];
        speed[l] = in.speed()[i + l];
        g_dry[l] = in.g_dry()[i + l];
        recess[l] = in.recess()[i + l];
      }
    }
    if (!four<kAvx2>(grp, r.rational_, fn, speed, g_dry, recess, m, &lanes))
      for (int l = 0; l < m; ++l) fold(records, out[i + l]);
  }

  // Contacts [0, n) of one race: groups of four, a last one of one by the scalar code (its
  // bits; ~600 instructions, a group ~800), of two or three padded.
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE double run(const RaceAdmittance &r, const ContactBatch &in,
                                        ContactAdmittance *out, std::size_t n)
  {
    v4d lanes = splat(std::numeric_limits<double>::infinity());
    double minimum = lanes[0];
    for (std::size_t i = 0; i < n; i += kLanes) {
      const int m = n - i < kLanes ? static_cast<int>(n - i) : kLanes;
      if (m == 1) {
        r.contact(in.fn()[i], in.speed()[i], in.g_dry()[i], in.recess()[i], out[i]);
        fold(minimum, out[i]);
      } else {
        group_of<kAvx2>(r, in, i, m, out, lanes, minimum);
      }
    }
    return fold<kAvx2>(minimum, lanes);
  }

  // The last contacts of two races in one group: la of race a (from its contact na - la), then
  // lb of race b, each lane with its race's constants (la, lb >= 1, la + lb <= 4, the same
  // permittivity form); padding as race a's. Each race's films into its minima, from the
  // records.
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE void mixed(const RaceAdmittance &ra, const ContactBatch &ia,
                                        ContactAdmittance *oa, std::size_t la,
                                        const RaceAdmittance &rb, const ContactBatch &ib,
                                        ContactAdmittance *ob, std::size_t lb, double &ma,
                                        double &mb)
  {
    const std::size_t na = ia.size(), nb = ib.size();
    RaceAdmittance::Blended &blended = ra.blended_;
    if (blended.partner != rb.serial_ || blended.la != la || blended.lb != lb) {
      blend(constants(ra), constants(rb), ra.rational_, la, lb, blended.splat.data());
      blended.partner = rb.serial_;
      blended.la = la;
      blended.lb = lb;
    }
    const RaceConstants &k = *reinterpret_cast<const RaceConstants *>(blended.splat.data());
    ContactAdmittance *lanes[kLanes];
    Group grp{&k, {&ra, &ra, &ra, &ra}, nullptr, lanes};
    v4d fn = splat(1.0), speed = splat(1.0), g_dry = splat(0.0), recess = splat(0.0);
    ContactAdmittance dropped;  // the padding lanes' records
    for (int l = 0; l < kLanes; ++l) {
      const bool in_a = static_cast<std::size_t>(l) < la,
                 in_b = !in_a && static_cast<std::size_t>(l) < la + lb;
      const ContactBatch &in = in_b ? ib : ia;
      const std::size_t at = in_b ? nb - lb + (l - la) : na - la + l;
      grp.race[l] = in_b ? &rb : &ra;
      lanes[l] = in_a ? oa + at : in_b ? ob + at : &dropped;
      if (!in_a && !in_b) continue;
      fn[l] = in.fn()[at];
      speed[l] = in.speed()[at];
      g_dry[l] = in.g_dry()[at];
      recess[l] = in.recess()[at];
    }
    four<kAvx2>(grp, ra.rational_, fn, speed, g_dry, recess, static_cast<int>(la + lb), nullptr);
    for (std::size_t l = 0; l < la; ++l) fold(ma, oa[na - la + l]);
    for (std::size_t l = 0; l < lb; ++l) fold(mb, ob[nb - lb + l]);
  }

  // The constants of a group of la lanes of race a, then lb of race b, lane by lane into `to`
  // (RaceConstants' layout; wt and dt only for the eight divisions' form: never read in the
  // one-fraction form). RaceConstants is 56 vectors in a row (static_assert above): its bytes
  // taken 32 at a time. Plain code (either instruction set's caller): rarely run.
  static void blend(const RaceConstants &ka, const RaceConstants &kb, bool rational,
                    std::size_t la, std::size_t lb, double *to)
  {
    v4i from_b = splat(0.0) > 1.0;  // no lane
    for (std::size_t l = la; l < la + lb; ++l) from_b[l] = -1;
    const char *pa = reinterpret_cast<const char *>(&ka), *pb = reinterpret_cast<const char *>(&kb);
    char *pk = reinterpret_cast<char *>(to);
    const std::size_t fields =
        rational ? offsetof(RaceConstants, wt) / sizeof(v4d) : sizeof(RaceConstants) / sizeof(v4d);
    for (std::size_t f = 0; f < fields; ++f) {
      v4d va, vb;
      __builtin_memcpy(&va, pa + f * sizeof(v4d), sizeof va);
      __builtin_memcpy(&vb, pb + f * sizeof(v4d), sizeof vb);
      const v4d v = select(from_b, vb, va);
      __builtin_memcpy(pk + f * sizeof(v4d), &v, sizeof v);
    }
  }

  // Whether two races' last contacts go in one group: both have some, they fit, and the races'
  // permittivity is in the same form.
  static bool mixes(const RaceAdmittance &ra, std::size_t la, const RaceAdmittance &rb,
                    std::size_t lb)
  {
    return la > 0 && lb > 0 && la + lb <= kLanes && ra.rational_ == rb.rational_;
  }
};

void RaceAdmittance::splat_constants(RaceAdmittance &r)
{
  RaceConstants k;
  k.a_coef = splat(r.in_.a_coef);
  k.b_coef = splat(r.in_.b_coef);
  k.central = splat(r.central_);
  k.ell_central = splat(r.ell_central_);
  k.minimum = splat(r.minimum_);
  k.ell_minimum = splat(r.ell_minimum_);
  k.inv_sigma = splat(r.inv_sigma_);
  k.area_coef = splat(r.area_coef_);
  k.inv_resistivity = splat(r.inv_resistivity_);
  k.q0_coef = splat(r.q0_coef_);
  k.sigma = splat(r.in_.sigma);
  k.r_wet = splat(r.in_.r_wet);
  k.p = splat(r.p_);
  k.q = splat(r.q_);
  k.r2 = splat(r.r2_);
  k.sp_coef = splat(r.sp_coef_);
  k.sq_coef = splat(r.sq_coef_);
  k.hertz_s = splat(r.hertz_s_);
  k.hertz_y = splat(r.hertz_y_);
  k.scale = splat(r.scale_);
  k.eps_const = splat(r.eps_const_);
  k.eps_pole = splat(r.eps_pole_);
  k.ga = splat(r.ga_);
  for (int i = 0; i < 8; ++i) {
    k.pc[i] = splat(r.pc_[i]);
    k.wt[i] = splat(r.wt_[i]);
    k.dt[i] = splat(r.dt_[i]);
  }
  for (int i = 0; i < 9; ++i) k.qc[i] = splat(r.qc_[i]);
  __builtin_memcpy(r.splat_.data(), &k, sizeof k);
}

namespace {

// One copy of the kernel per use and instruction set (it is inlined where it is used).
// Each returns its races' smallest film.minimum (RaceLanes::fold).
__attribute__((target("avx2"))) double contacts_avx2(const RaceAdmittance &r,
                                                     const ContactBatch &in,
                                                     ContactAdmittance *out, std::size_t n)
{
  return RaceLanes::run<true>(r, in, out, n);
}

double contacts_sse2(const RaceAdmittance &r, const ContactBatch &in, ContactAdmittance *out,
                     std::size_t n)
{
  return RaceLanes::run<false>(r, in, out, n);
}

__attribute__((target("avx2"))) void mixed_avx2(const RaceAdmittance &ra, const ContactBatch &ia,
                                                ContactAdmittance *oa, std::size_t la,
                                                const RaceAdmittance &rb, const ContactBatch &ib,
                                                ContactAdmittance *ob, std::size_t lb,
                                                double &ma, double &mb)
{
  RaceLanes::mixed<true>(ra, ia, oa, la, rb, ib, ob, lb, ma, mb);
}

void mixed_sse2(const RaceAdmittance &ra, const ContactBatch &ia, ContactAdmittance *oa,
                std::size_t la, const RaceAdmittance &rb, const ContactBatch &ib,
                ContactAdmittance *ob, std::size_t lb, double &ma, double &mb)
{
  RaceLanes::mixed<false>(ra, ia, oa, la, rb, ib, ob, lb, ma, mb);
}

bool use_avx2(RaceAdmittance::Isa isa)
{
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2 && isa == RaceAdmittance::Isa::best;
}

}  // namespace

void RaceAdmittance::contacts(const ContactBatch &in, ContactAdmittance *out, Isa isa) const
{
  (use_avx2(isa) ? contacts_avx2 : contacts_sse2)(*this, in, out, in.size());
}

std::array<RaceAdmittance::Minima, 2> RaceAdmittance::contacts(
    const RaceAdmittance &a, const ContactBatch &in_a, ContactAdmittance *out_a,
    const RaceAdmittance &b, const ContactBatch &in_b, ContactAdmittance *out_b, Isa isa)
{
  const bool avx2 = use_avx2(isa);
  const auto each = avx2 ? contacts_avx2 : contacts_sse2;
  const std::size_t na = in_a.size(), nb = in_b.size();
  const std::size_t la = na % kLanes, lb = nb % kLanes;
  double ma, mb;
  if (!RaceLanes::mixes(a, la, b, lb)) {
    ma = each(a, in_a, out_a, na);
    mb = each(b, in_b, out_b, nb);
  } else {
    ma = each(a, in_a, out_a, na - la);
    mb = each(b, in_b, out_b, nb - lb);
    (avx2 ? mixed_avx2 : mixed_sse2)(a, in_a, out_a, la, b, in_b, out_b, lb, ma, mb);
  }
  // The smallest lambda is the smallest film's (RaceLanes::fold).
  return {Minima{ma, ma * a.inv_sigma_}, Minima{mb, mb * b.inv_sigma_}};
}

}  // namespace ohmdem::lubrication
