// SPDX-License-Identifier: GPL-2.0-or-later
// The batched kernel of RaceAdmittance::contacts (its friend RaceLanes), for its two
// translation units and no other: race_admittance_batch.cpp (SSE2 and AVX2 under function
// targets, the dispatch) and race_admittance_avx512.cpp (the whole file built for AVX-512F and
// DQ: GCC 12 lowers eight-lane comparisons lane by lane in code built for a lesser target and
// only retargeted per function). The kernel's functions are always inlined into their caller,
// so the AVX-512 file's build of them is never linked in place of the other's:
// tests/lib/lubrication/CMakeLists.txt checks that its object defines no weak symbol and runs
// no initializer.
#ifndef OHMDEM_LUBRICATION_RACE_LANES_H
#define OHMDEM_LUBRICATION_RACE_LANES_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "common/constants.h"
#include "common/estrin.h"
#include "common/fast_exp_log.h"
#include "common/lanes.h"
#include "lubrication/race_admittance.h"
#include "lubrication/race_lane_functions.h"

namespace ohmdem::lubrication {

using lanes::Int;
using lanes::Isa;
using lanes::kLanesOf;
using lanes::select;
using lanes::splat;
using lanes::Uint;
using lanes::v4d;
using lanes::v4i;
using lanes::v8d;
constexpr int kLanes = 4;  // a group's lanes but for AVX-512's groups of eight
using race_lanes::aliasing;
using race_lanes::erfc_where;
using race_lanes::exp_small;
using race_lanes::form_mean;
using race_lanes::Forms;
using race_lanes::in_log_range;
using race_lanes::log_where;

inline const double kSqrtHalf = std::sqrt(0.5), kSqrtPi = std::sqrt(kPi);  // as race_admittance.cpp

// RaceAdmittance's constants as the kernel's operands, four lanes each (its splat_ holds them
// in this layout), or eight (splat8_). A group of one race reads its race's; a group of two
// races' contacts (four lanes), lanes blended from both.
template <class V>
struct RaceConstantsOf {
  V a_coef, b_coef, central, ell_central, minimum, ell_minimum, inv_sigma, area_coef,
      inv_resistivity, q0_coef, sigma, r_wet, p, q, r2, sp_coef, sq_coef, hertz_s, hertz_y, scale,
      eps_const, eps_pole, ga;
  V pc[8], qc[9], wt[8], dt[8];
};
using RaceConstants = RaceConstantsOf<v4d>;

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

// What a group of four or eight (V) reads: the constants, each lane's race (for the scalar
// code's rare lanes) and where each lane's record goes: base[l] for one race's group (lanes
// null), else lanes[l] (four lanes only).
template <class V>
struct Group {
  const RaceConstantsOf<V> *k;
  const RaceAdmittance *race[kLanesOf<V>];
  ContactAdmittance *base;
  ContactAdmittance *const *lanes;
  ContactAdmittance &out(int l) const { return lanes ? *lanes[l] : base[l]; }
};

// Friend of RaceAdmittance: its constants.
struct RaceLanes {
  static_assert(sizeof(RaceConstants) == sizeof(double) * RaceAdmittance::kSplat,
                "RaceAdmittance::splat_ holds RaceConstants");
  static_assert(alignof(RaceConstants) <= 32, "splat_ is 32-byte aligned");
  static_assert(sizeof(RaceConstantsOf<v8d>) == sizeof(double) * RaceAdmittance::kSplat8,
                "RaceAdmittance::splat8_ holds RaceConstantsOf<v8d>");
  static_assert(alignof(RaceConstantsOf<v8d>) <= 64, "splat8_ is 64-byte aligned");

  template <class V = v4d>
  static OHMDEM_LANES_INLINE const RaceConstantsOf<V> &constants(const RaceAdmittance &r)
  {
    if constexpr (kLanesOf<V> == 8)
      return *reinterpret_cast<const RaceConstantsOf<V> *>(r.splat8_.data());
    else
      return *reinterpret_cast<const RaceConstantsOf<V> *>(r.splat_.data());
  }

  // A race's smallest film.minimum: over its full groups lane by lane (folded into one at the
  // race's end), and over the records written one by one. Its lambda is minimum / sigma, each
  // record's film.minimum * inv_sigma_ (contact() and four()): rounding is monotonic, so the
  // smallest lambda is the smallest film's, bit for bit (RaceAdmittance::contacts, at the end).
  static OHMDEM_LANES_INLINE void fold(double &minimum, const ContactAdmittance &c)
  {
    minimum = std::min(minimum, c.film.minimum);
  }
  template <Isa kIsa>
  static OHMDEM_LANES_INLINE double fold(double minimum, v4d lanes)
  {
    const v4d pairs = lanes::min<kIsa>(lanes, __builtin_shuffle(lanes, v4i{2, 3, 0, 1}));
    const v4d all = lanes::min<kIsa>(pairs, __builtin_shuffle(pairs, v4i{1, 0, 3, 2}));
    return std::min(minimum, all[0]);
  }
  // Eight lanes: their halves' min, then as four.
  static OHMDEM_LANES_INLINE v4d halves_min(v8d lanes)
  {
    v4d half[2];
    __builtin_memcpy(half, &lanes, sizeof half);
    return lanes::min(half[0], half[1]);
  }

  template <class V>
  static OHMDEM_LANES_INLINE V permittivity(bool rational, const RaceConstantsOf<V> &k, V q0)
  {
    if (rational) {
      const V num = estrin::polynomial<8>(k.pc, q0), den = estrin::polynomial<9>(k.qc, q0);
      return k.eps_const + k.eps_pole * (num / den);
    }
    V sum = splat<V>(0.0);
    for (int i = 0; i < 8; ++i) sum += k.wt[i] / (k.ga + q0 * k.dt[i]);
    return k.eps_const + k.eps_pole * sum;
  }

  // Lanes [0, m) of fn ... into the group's records; the comments are RaceAdmittance::contact's
  // steps. `rational`: the races' permittivity form (the same for every lane). Returns whether
  // the group's films went into `minima` (one race's full group, stored from the lanes); else the
  // caller takes them from the records.
  template <Isa kIsa, class V>
  static OHMDEM_LANES_INLINE bool four(const Group<V> &grp, bool rational, V fn, V speed, V g_dry,
                                       V recess, int m, V *minima)
  {
    using I = Int<V>;
    constexpr int kWidth = kLanesOf<V>;
    const RaceConstantsOf<V> &k = *grp.k;
    // A contact that does not roll (its cube root) or whose inputs leave log_fast's range: the
    // scalar code.
    const I moving = (speed > 0.0) & (fn > 0.0);
    const I odd = ~(moving & in_log_range(speed) & in_log_range(fn));
    const I go = ~odd;
    const V ls = lanes::log<kIsa>(select<kIsa>(go, speed, splat<V>(1.0)));
    const V lw = lanes::log<kIsa>(select<kIsa>(go, fn, splat<V>(1.0)));
    const V cb = lanes::exp<kIsa>(lw * (1.0 / 3.0));
    const V a = k.a_coef * cb, b = k.b_coef * cb;
    // The films.
    const V central_power = lanes::exp<kIsa>(0.67 * ls - 0.067 * lw);
    const V central = select<kIsa>(go, k.central * central_power * k.ell_central, splat<V>(0.0));
    const V z = 0.01 * ls - 0.006 * lw;
    const I near = (z < 0.25) & (z > -0.25);
    V power_min = central_power * exp_small(z);
    if (!lanes::all<kIsa>(near))
      power_min =
          select<kIsa>(near, power_min,
                       lanes::exp<kIsa>(select<kIsa>(near, splat<V>(0.0), 0.68 * ls - 0.073 * lw)));
    const V minimum = select<kIsa>(go, k.minimum * power_min * k.ell_minimum, splat<V>(0.0));
    const V lambda = minimum * k.inv_sigma;
    const V gap = minimum + recess;
    const V area = k.area_coef * cb * cb;
    const V h = central + recess;
    const I film = (h > 0.0) & (area > 0.0);
    const V area_h = select<kIsa>(film, area / select<kIsa>(film, h, splat<V>(1.0)), splat<V>(0.0));
    const V leak = area_h * k.inv_resistivity;
    // The metallic fraction, or 0 when it cannot matter: the cheap bound from x = 6, unless
    // the bound cannot pass, ...
    const V xm = select<kIsa>(recess > 0.0, gap * k.inv_sigma, lambda) * kSqrtHalf;
    const I big = xm >= 6.0;
    // A padded group's padding lanes [m, kWidth) (records dropped) need no fraction: left to
    // them, the padding contact's thin film would take every padded group through erfc.
    V index;
    for (int l = 0; l < kWidth; ++l) index[l] = l;
    I negligible = index >= static_cast<double>(m);
    const I far = ~negligible & (xm > 5.5);  // real lanes where the tail bound applies
    I hopeless = far & 0;
    if (lanes::any<kIsa>(far)) {
      // min(floor(v), 1000) as floor(min(v, 1000)), the floor through 2^52 (0 <= v <= 1000).
      const V v =
          lanes::min<kIsa>(xm * xm * (1.4426950408889634 * (1.0 - 1e-12)), splat<V>(1000.0));
      const V shifted = v + 0x1p52;
      const I e = ((I)shifted - (I)splat<V>(0x1p52)) + ((shifted - 0x1p52) > v);
      const V cheap = 0.1 * (V)((Uint<V>)(1023 - e) << 52);  // 0.1 pow2_neg(e)
      negligible |= big & (cheap <= 0x1p-54) & (cheap * g_dry <= 1e-17 * leak);
      // ... unless the bound's lower bound 2^-(e+2) / (1.7725 x) already fails a test.
      const V low = (V)((Uint<V>)(1021 - e) << 52), scale = (1.7725 * 1.0001) * xm;
      hopeless = far & ~negligible & (v < 1000.0) &
                 ((low > 0x1p-54 * scale) | (low * g_dry > 1e-17 * leak * scale));
    }
    // ... then the bound itself from 5.5.
    const I bound_lanes = ~negligible & ~hopeless & (xm > 5.5);
    if (lanes::any<kIsa>(bound_lanes)) {
      const V e = -xm * xm;
      const I fast = bound_lanes & (e > -708.0) & (e < 709.0);  // exp_fast's range
      V ex = lanes::exp<kIsa>(select<kIsa>(fast, e, splat<V>(0.0)));
      if (!lanes::all<kIsa>(fast | ~bound_lanes))
        for (int l = 0; l < kWidth; ++l)
          if (bound_lanes[l] && !fast[l]) ex[l] = exp_fast(e[l]);
      const V bound = ex / (xm * kSqrtPi);
      negligible |= bound_lanes & (bound <= 0x1p-54) & (bound * g_dry <= 1e-17 * leak);
    }
    const V metallic =
        lanes::any<kIsa>(~negligible) ? erfc_where<kIsa>(~negligible, xm) : splat<V>(0.0);
    const V free = 1.0 - metallic;
    V g = metallic * g_dry;
    const I zone = film & (free > 0.0);
    V c_hertz = splat<V>(0.0);
    if (lanes::any<kIsa>(zone)) {
      const V q0 = k.q0_coef * cb;
      c_hertz =
          select<kIsa>(zone, free * kEpsilon0 * permittivity(rational, k, q0) * area_h, c_hertz);
      g = select<kIsa>(zone, g + free * leak, g);
    }
    // The gap's closed form while the wetted circle holds the ellipse (else the scalar code's
    // gap_capacitance).
    const V h0 = lanes::max<kIsa>(central, k.sigma) + recess;
    const I wet = (k.r_wet > a) & (k.r_wet > b) & (a > 0.0) & (b > 0.0);
    const Forms<V> outer =
        form_mean(lanes::sqrt<kIsa>(h0 * k.p + k.r2), lanes::sqrt<kIsa>(h0 * k.q + k.r2));
    const V inv_cb = 1.0 / cb, sp = k.sp_coef * inv_cb, sq = k.sq_coef * inv_cb;
    const Forms<V> inner =
        form_mean(lanes::sqrt<kIsa>(h0 * sp * sp + 1.0), lanes::sqrt<kIsa>(h0 * sq * sq + 1.0));
    const V x = outer.s * k.hertz_s * inv_cb / inner.s, y = outer.y * k.hertz_y / inner.y;
    const V c_outer = k.scale * (2.0 * log_where<kIsa>(wet, x) + aliasing<kIsa>(wet, y));
    // The records, lane by lane (a full group with no odd lane and the closed form in every
    // lane: the lanes' indices are constants, so no vector goes through memory).
    if (m == kWidth && !lanes::any<kIsa>(odd) && lanes::all<kIsa>(wet)) {
      // Fields 0-3 and 4-7 of the four records transposed (four rows of four), the ninth alone.
      store_rows(grp, 0, central, minimum, lambda, metallic);
      store_rows(grp, 4, c_hertz, c_outer, g, gap);
#pragma GCC unroll 8
      for (int l = 0; l < kWidth; ++l) grp.out(l).g_dry = g_dry[l];
      if (!minima) return false;
      *minima = lanes::min<kIsa>(*minima, minimum);
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
  static OHMDEM_LANES_INLINE void store_rows(const Group<v4d> &grp, int first, v4d a, v4d b, v4d c,
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
  // Eight lanes (one race's group: base): each half as four.
  static OHMDEM_LANES_INLINE void store_rows(const Group<v8d> &grp, int first, v8d a, v8d b, v8d c,
                                             v8d d)
  {
    v4d ha[2], hb[2], hc[2], hd[2];
    __builtin_memcpy(ha, &a, sizeof a);
    __builtin_memcpy(hb, &b, sizeof b);
    __builtin_memcpy(hc, &c, sizeof c);
    __builtin_memcpy(hd, &d, sizeof d);
    for (int h = 0; h < 2; ++h) {
      const Group<v4d> half{nullptr, {}, grp.base + kLanes * h, nullptr};
      store_rows(half, first, ha[h], hb[h], hc[h], hd[h]);
    }
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

  // One race's contacts [i, i + m) (1 < m <= the group's lanes) as a group; padding: a
  // loaded, rolling contact whose record is dropped. The full groups' films into `lanes`.
  template <Isa kIsa, class V>
  static OHMDEM_LANES_INLINE void group_of(const RaceAdmittance &r, const ContactBatch &in,
                                           std::size_t i, int m, ContactAdmittance *out, V &lanes,
                                           double &records)
  {
    constexpr int kWidth = kLanesOf<V>;
    Group<V> grp{&constants<V>(r), {}, out + i, nullptr};
    for (int l = 0; l < kWidth; ++l) grp.race[l] = &r;
    V fn, speed, g_dry, recess;
    if (m == kWidth) {
      __builtin_memcpy(&fn, in.fn() + i, sizeof fn);
      __builtin_memcpy(&speed, in.speed() + i, sizeof speed);
      __builtin_memcpy(&g_dry, in.g_dry() + i, sizeof g_dry);
      __builtin_memcpy(&recess, in.recess() + i, sizeof recess);
    } else if constexpr (kIsa == Isa::avx512) {
      // Lanes [0, m) loaded, the others the padding (masked loads: no access past m).
      fn = lanes::load_first(in.fn() + i, m, splat<V>(1.0));
      speed = lanes::load_first(in.speed() + i, m, splat<V>(1.0));
      g_dry = lanes::load_first(in.g_dry() + i, m, splat<V>(0.0));
      recess = lanes::load_first(in.recess() + i, m, splat<V>(0.0));
    } else {
      fn = speed = splat<V>(1.0);
      g_dry = recess = splat<V>(0.0);
      for (int l = 0; l < m; ++l) {
        fn[l] = in.fn()[i + l];
        speed[l] = in.speed()[i + l];
        g_dry[l] = in.g_dry()[i + l];
        recess[l] = in.recess()[i + l];
      }
    }
    if (!four<kIsa>(grp, r.rational_, fn, speed, g_dry, recess, m, &lanes))
      for (int l = 0; l < m; ++l) fold(records, out[i + l]);
  }

  // Contacts [0, n) of one race: groups of four, a last one of one by the scalar code (its
  // bits; ~600 instructions, a group ~800), of two or three padded. AVX-512: first groups of
  // eight while five or more are left (the last one padded: eight lanes cost ~1.2 times four),
  // then at most four as AVX2's.
  template <Isa kIsa>
  static OHMDEM_LANES_INLINE double run(const RaceAdmittance &r, const ContactBatch &in,
                                        ContactAdmittance *out, std::size_t n)
  {
    constexpr Isa kFour = kIsa == Isa::avx512 ? Isa::avx2 : kIsa;
    v4d lanes = splat<v4d>(std::numeric_limits<double>::infinity());
    double minimum = lanes[0];
    std::size_t i = 0;
    if constexpr (kIsa == Isa::avx512) {
      v8d wide = splat<v8d>(minimum);
      for (; i + 5 <= n; i += 8)
        group_of<kIsa>(r, in, i, static_cast<int>(std::min<std::size_t>(n - i, 8)), out, wide,
                       minimum);
      lanes = halves_min(wide);
    }
    for (; i < n; i += kLanes) {
      const int m = n - i < kLanes ? static_cast<int>(n - i) : kLanes;
      if (m == 1) {
        r.contact(in.fn()[i], in.speed()[i], in.g_dry()[i], in.recess()[i], out[i]);
        fold(minimum, out[i]);
      } else {
        group_of<kFour>(r, in, i, m, out, lanes, minimum);
      }
    }
    return fold<kFour>(minimum, lanes);
  }

  // race_admittance_batch.cpp's alone (the AVX-512 file never reads them): the shared group
  // of two races' last contacts, the race's constants in lanes, and the tails.
  // The last contacts of two races in one group (la of race a, then lb of race b).
  template <Isa kIsa>
  static void mixed(const RaceAdmittance &ra, const ContactBatch &ia, ContactAdmittance *oa,
                    std::size_t la, const RaceAdmittance &rb, const ContactBatch &ib,
                    ContactAdmittance *ob, std::size_t lb, double &ma, double &mb);
  // The blended constants of such a group.
  static void blend(const RaceConstants &ka, const RaceConstants &kb, bool rational, std::size_t la,
                    std::size_t lb, double *to);
  // The race's constants, each in every lane of V.
  template <class V>
  static RaceConstantsOf<V> in_lanes(const RaceAdmittance &r);
  // The contacts a race of n leaves to the shared group.
  static std::size_t tail(Isa isa, std::size_t n);
  // Whether two races' last contacts go in one group.
  static bool mixes(const RaceAdmittance &ra, std::size_t la, const RaceAdmittance &rb,
                    std::size_t lb);
};

// RaceLanes::run<Isa::avx512> (race_admittance_avx512.cpp): call only where the CPU has
// AVX-512F and DQ.
double contacts_avx512(const RaceAdmittance &r, const ContactBatch &in, ContactAdmittance *out,
                       std::size_t n);

}  // namespace ohmdem::lubrication

#endif
