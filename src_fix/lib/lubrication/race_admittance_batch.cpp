// SPDX-License-Identifier: GPL-2.0-or-later
// RaceAdmittance::contacts: a race's contacts four per operation (common/lanes4.h), each lane
// the same operations in the same order as RaceAdmittance::contact, so each contact's record
// is that function's bit for bit (the bench's deck gives the same numbers as the scalar path,
// with any number of processes). The scalar function's branches are masks; a lane that would
// take one of its rare branches (inputs outside the inline functions' ranges, erfc below 0.5,
// the wetted circle not holding the ellipse) is redone by the scalar code, alone. A last group
// of one contact goes to the scalar code too (cheaper than four lanes); one of two or three is
// padded with a plain contact that is computed and dropped. The body is compiled
// twice, for SSE2 and AVX2 (there with lanes4.h's gathers, sign masks and blends: kAvx2),
// chosen at run time: the same bits (no FMA: the file is built with -ffp-contract=off).
#include <cmath>
#include <cstddef>

#include "common/constants.h"
#include "common/fast_erfc.h"
#include "common/fast_exp_log.h"
#include "common/lanes4.h"
#include "lubrication/gap_forms.h"
#include "lubrication/race_admittance.h"

namespace ohmdem::lubrication {

namespace {

using lanes::kLanes;
using lanes::select;
using lanes::splat;
using lanes::v4d;
using lanes::v4i;
using lanes::v4u;

const double kSqrtHalf = std::sqrt(0.5), kSqrtPi = std::sqrt(kPi);  // as race_admittance.cpp

OHMDEM_LANES_INLINE v4i in_log_range(v4d x)
{
  return (x >= 2.3e-308) & (x <= 1.7e308);  // log_fast's
}

// race_admittance.cpp's exp_small.
OHMDEM_LANES_INLINE v4d exp_small(v4d z)
{
  v4d p = splat(1.0 / 6227020800.0);
  for (const double c :
       {1.0 / 479001600.0, 1.0 / 39916800.0, 1.0 / 3628800.0, 1.0 / 362880.0, 1.0 / 40320.0,
        1.0 / 5040.0, 1.0 / 720.0, 1.0 / 120.0, 1.0 / 24.0, 1.0 / 6.0, 0.5, 1.0, 1.0})
    p = c + z * p;
  return p;
}

// gap_forms::form_mean.
struct Forms {
  v4d s, y;
};
OHMDEM_LANES_INLINE Forms form_mean(v4d sa, v4d sb)
{
  const v4d s = sa + sb;
  v4d r = (sa - sb) / s;
  for (int i = 0; i < 6; ++i) r *= r;
  return {s, 1.0 + r};
}

// log_fast where `use`, by lanes (odd lanes by the scalar function); 0 elsewhere. kAvx2: the
// body of contacts_avx2 (lanes4.h's gathers and sign masks).
template <bool kAvx2>
OHMDEM_LANES_INLINE v4d log_where(v4i use, v4d x)
{
  const v4i fast = use & in_log_range(x);
  v4d r = lanes::log<kAvx2>(select<kAvx2>(fast, x, splat(1.0)));
  if (!lanes::all<kAvx2>(fast | ~use))
    for (int l = 0; l < kLanes; ++l)
      if (use[l] && !fast[l]) r[l] = log_fast(x[l]);
  return r;
}

// gap_forms::aliasing(y, log_fast) where `use`.
template <bool kAvx2>
OHMDEM_LANES_INLINE v4d aliasing(v4i use, v4d y)
{
  const v4d e = y - 1.0;
  const v4i small = (e < 1e-6) & (e > -1e-6);  // fabs(e) < 1e-6
  const v4d series = e * (1.0 - e * (0.5 - e * (1.0 / 3.0 - 0.25 * e))) / gap_forms::kQuarter;
  if (lanes::all<kAvx2>(small | ~use)) return series;
  return select<kAvx2>(small, series, log_where<kAvx2>(use & ~small, y) / gap_forms::kQuarter);
}

// erfc_fast's coefficients g_k, each in four lanes: a vector operand of the addition (no
// broadcast per term; the same values, so the same bits).
struct ErfcLanes {
  v4d g[22];
};
const ErfcLanes kErfcLanes = [] {
  ErfcLanes t{};
  for (int k = 0; k < 22; ++k) t.g[k] = splat(kErfcG[k]);
  return t;
}();

// erfc_fast where `use`; 0 elsewhere.
template <bool kAvx2>
OHMDEM_LANES_INLINE v4d erfc_where(v4i use, v4d xm)
{
  const v4i fast = use & (xm >= 0.5) & (xm <= 26.0);
  v4d f = splat(0.0);
  if (lanes::any<kAvx2>(fast)) {
    const v4d x = select<kAvx2>(fast, xm, splat(1.0));
    const v4d t = 2.0 / (2.0 + x), s = 2.0 * t - 1.0;
    v4d g = kErfcLanes.g[21];
    // Unrolled: two instructions a term.
#pragma GCC unroll 21
    for (int k = 20; k >= 0; --k) g = g * s + kErfcLanes.g[k];
    f = select<kAvx2>(fast, t * lanes::exp<kAvx2>(g - x * x), f);
  }
  if (!lanes::all<kAvx2>(fast | ~use))
    for (int l = 0; l < kLanes; ++l)
      if (use[l] && !fast[l]) f[l] = erfc_fast(xm[l]);
  return f;
}

}  // namespace

// Friend of RaceAdmittance: its constants.
struct RaceLanes {
  static OHMDEM_LANES_INLINE v4d permittivity(const RaceAdmittance &r, v4d q0)
  {
    if (r.rational_) {
      v4d num = splat(r.pc_[7]), den = splat(r.qc_[8]);
      for (int k = 6; k >= 0; --k) num = num * q0 + r.pc_[k];
      for (int k = 7; k >= 0; --k) den = den * q0 + r.qc_[k];
      return r.eps_const_ + r.eps_pole_ * (num / den);
    }
    v4d sum = splat(0.0);
    for (int i = 0; i < 8; ++i) sum += r.wt_[i] / (r.ga_ + q0 * r.dt_[i]);
    return r.eps_const_ + r.eps_pole_ * sum;
  }

  // Lanes [0, m) of fn ... into out[0, m); the comments are RaceAdmittance::contact's steps.
  template <bool kAvx2>
  static OHMDEM_LANES_INLINE void four(const RaceAdmittance &r, v4d fn, v4d speed, v4d g_dry,
                                       v4d recess, int m, ContactAdmittance *out)
  {
    const RaceInput &ri = r.in_;
    v4i odd = ~((fn >= 2.3e-308) & (fn <= 1e300));  // cbrt_fast's range: the scalar code
    const v4d cb = lanes::cbrt(select<kAvx2>(odd, splat(1.0), fn));
    const v4d a = ri.a_coef * cb, b = ri.b_coef * cb;
    // The films (fn in range is in log_fast's range too).
    const v4i moving = (speed > 0.0) & (fn > 0.0);
    odd |= moving & ~in_log_range(speed);
    const v4i go = moving & ~odd;
    const v4d ls = lanes::log<kAvx2>(select<kAvx2>(go, speed, splat(1.0)));
    const v4d lw = lanes::log<kAvx2>(select<kAvx2>(go, fn, splat(1.0)));
    const v4d central_power = lanes::exp<kAvx2>(0.67 * ls - 0.067 * lw);
    const v4d central = select<kAvx2>(go, r.central_ * central_power * r.ell_central_, splat(0.0));
    const v4d z = 0.01 * ls - 0.006 * lw;
    const v4i near = (z < 0.25) & (z > -0.25);
    v4d power_min = central_power * exp_small(z);
    if (!lanes::all<kAvx2>(near))
      power_min =
          select<kAvx2>(near, power_min,
                        lanes::exp<kAvx2>(select<kAvx2>(near, splat(0.0), 0.68 * ls - 0.073 * lw)));
    const v4d minimum = select<kAvx2>(go, r.minimum_ * power_min * r.ell_minimum_, splat(0.0));
    const v4d lambda = minimum * r.inv_sigma_;
    const v4d gap = minimum + recess;
    const v4d area = r.area_coef_ * cb * cb;
    const v4d h = central + recess;
    const v4i film = (h > 0.0) & (area > 0.0);
    const v4d area_h = select<kAvx2>(film, area / select<kAvx2>(film, h, splat(1.0)), splat(0.0));
    const v4d leak = area_h * r.inv_resistivity_;
    // The metallic fraction, or 0 when it cannot matter: the cheap bound from x = 6 ...
    const v4d xm = select<kAvx2>(recess > 0.0, gap * r.inv_sigma_, lambda) * kSqrtHalf;
    const v4i big = xm >= 6.0;
    v4i negligible = big & 0;
    if (lanes::any<kAvx2>(big)) {
      // min(floor(v), 1000) as floor(min(v, 1000)), the floor through 2^52 (0 <= v <= 1000).
      const v4d v =
          lanes::min<kAvx2>(xm * xm * (1.4426950408889634 * (1.0 - 1e-12)), splat(1000.0));
      const v4d shifted = v + 0x1p52;
      const v4i k = ((v4i)shifted - (v4i)splat(0x1p52)) + ((shifted - 0x1p52) > v);
      const v4d cheap = 0.1 * (v4d)((v4u)(1023 - k) << 52);  // 0.1 pow2_neg(k)
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
      const v4d q0 = r.q0_coef_ * cb;
      c_hertz = select<kAvx2>(zone, free * kEpsilon0 * permittivity(r, q0) * area_h, c_hertz);
      g = select<kAvx2>(zone, g + free * leak, g);
    }
    // The gap's closed form while the wetted circle holds the ellipse (else the scalar code's
    // gap_capacitance).
    const v4d h0 = lanes::max<kAvx2>(central, splat(ri.sigma)) + recess;
    const v4d r_wet = splat(ri.r_wet);
    const v4i wet = (r_wet > a) & (r_wet > b) & (a > 0.0) & (b > 0.0);
    const Forms outer = form_mean(lanes::sqrt(h0 * r.p_ + r.r2_), lanes::sqrt(h0 * r.q_ + r.r2_));
    const v4d inv_cb = 1.0 / cb, sp = r.sp_coef_ * inv_cb, sq = r.sq_coef_ * inv_cb;
    const Forms inner = form_mean(lanes::sqrt(h0 * sp * sp + 1.0), lanes::sqrt(h0 * sq * sq + 1.0));
    const v4d x = outer.s * r.hertz_s_ * inv_cb / inner.s, y = outer.y * r.hertz_y_ / inner.y;
    const v4d c_outer = r.scale_ * (2.0 * log_where<kAvx2>(wet, x) + aliasing<kAvx2>(wet, y));
    // The records, lane by lane (a full group with no odd lane and the closed form in every
    // lane: the lanes' indices are constants, so no vector goes through memory).
    if (m == kLanes && !lanes::any<kAvx2>(odd) && lanes::all<kAvx2>(wet)) {
#pragma GCC unroll 4
      for (int l = 0; l < kLanes; ++l)
        record(out[l], central[l], minimum[l], lambda[l], metallic[l], c_hertz[l], c_outer[l], g[l],
               gap[l], g_dry[l]);
      return;
    }
    for (int l = 0; l < m; ++l) {
      if (odd[l]) {
        r.contact(fn[l], speed[l], g_dry[l], recess[l], out[l]);
        continue;
      }
      record(out[l], central[l], minimum[l], lambda[l], metallic[l], c_hertz[l],
             wet[l] ? c_outer[l]
                    : gap_capacitance(GapGeometry{h0[l], ri.rx, ri.ry, a[l], b[l], ri.r_wet},
                                      ri.eps_r),
             g[l], gap[l], g_dry[l]);
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

  template <bool kAvx2>
  static OHMDEM_LANES_INLINE void run(const RaceAdmittance &r, const ContactBatch &in,
                                      ContactAdmittance *out)
  {
    const std::size_t n = in.size();
    for (std::size_t i = 0; i < n; i += kLanes) {
      const int m = n - i < kLanes ? static_cast<int>(n - i) : kLanes;
      if (m == 1) {  // one contact: the scalar code (its bits; ~600 instructions, a group ~1100)
        r.contact(in.fn()[i], in.speed()[i], in.g_dry()[i], in.recess()[i], out[i]);
        continue;
      }
      v4d fn, speed, g_dry, recess;
      if (m == kLanes) {
        __builtin_memcpy(&fn, in.fn() + i, sizeof fn);
        __builtin_memcpy(&speed, in.speed() + i, sizeof speed);
        __builtin_memcpy(&g_dry, in.g_dry() + i, sizeof g_dry);
        __builtin_memcpy(&recess, in.recess() + i, sizeof recess);
      } else {
        // Padding: a loaded, rolling contact (its record is dropped).
        fn = speed = splat(1.0);
        g_dry = recess = splat(0.0);
        for (int l = 0; l < m; ++l) {
          fn[l] = in.fn()[i + l];
          speed[l] = in.speed()[i + l];
          g_dry[l] = in.g_dry()[i + l];
          recess[l] = in.recess()[i + l];
        }
      }
      four<kAvx2>(r, fn, speed, g_dry, recess, m, out + i);
    }
  }
};

namespace {

__attribute__((target("avx2"))) void contacts_avx2(const RaceAdmittance &r, const ContactBatch &in,
                                                   ContactAdmittance *out)
{
  RaceLanes::run<true>(r, in, out);
}

void contacts_sse2(const RaceAdmittance &r, const ContactBatch &in, ContactAdmittance *out)
{
  RaceLanes::run<false>(r, in, out);
}

}  // namespace

void RaceAdmittance::contacts(const ContactBatch &in, ContactAdmittance *out, Isa isa) const
{
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && isa == Isa::best)
    contacts_avx2(*this, in, out);
  else
    contacts_sse2(*this, in, out);
}

}  // namespace ohmdem::lubrication
