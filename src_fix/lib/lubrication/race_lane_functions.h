// SPDX-License-Identifier: GPL-2.0-or-later
// The lane forms of race_admittance.cpp's helpers for the batched kernel (race_lanes.h, its
// only includer, whose two files are compiled with -ffp-contract=off and -fno-math-errno): log_fast's range test, exp_small, gap_forms' form mean and aliasing term,
// log_fast and erfc_fast where a mask asks for them, on four or eight lanes (V). Each lane does
// the scalar function's operations in its order (the same bits); kIsa picks lanes.h's forms.
#ifndef OHMDEM_LUBRICATION_RACE_LANE_FUNCTIONS_H
#define OHMDEM_LUBRICATION_RACE_LANE_FUNCTIONS_H

#include "common/estrin.h"
#include "common/fast_erfc.h"
#include "common/fast_exp_log.h"
#include "common/lanes.h"
#include "lubrication/exp_small.h"
#include "lubrication/gap_forms.h"

namespace ohmdem::lubrication::race_lanes {

using lanes::Int;
using lanes::Isa;
using lanes::kLanesOf;
using lanes::select;
using lanes::splat;

template <class V>
OHMDEM_LANES_INLINE Int<V> in_log_range(V x)
{
  return (x >= 2.3e-308) & (x <= 1.7e308);  // log_fast's
}

// A polynomial's coefficients, each in every lane of V: a vector operand of each operation (no
// broadcast per term; the same values, so the same bits). constexpr: no initializer at run time.
template <int N, class V>
struct LaneCoefficients {
  V c[N];
};
template <class V, int N>
constexpr LaneCoefficients<N, V> in_lanes(const double (&c)[N])
{
  LaneCoefficients<N, V> t{};
  for (int k = 0; k < N; ++k) t.c[k] = splat<V>(c[k]);
  return t;
}

// exp_small.h's exp_small.
template <class V>
inline constexpr LaneCoefficients<14, V> kExpSmallLanes = in_lanes<V>(kExpSmall);
template <class V>
OHMDEM_LANES_INLINE V exp_small(V z)
{
  return 1.0 + z * estrin::polynomial<13>(kExpSmallLanes<V>.c + 1, z);
}

// gap_forms::form_mean.
template <class V>
struct Forms {
  V s, y;
};
template <class V>
OHMDEM_LANES_INLINE Forms<V> form_mean(V sa, V sb)
{
  const V s = sa + sb;
  V r = (sa - sb) / s;
  for (int i = 0; i < 6; ++i) r *= r;
  return {s, 1.0 + r};
}

// log_fast where `use`, by lanes (odd lanes by the scalar function); 0 elsewhere.
template <Isa kIsa, class V>
OHMDEM_LANES_INLINE V log_where(Int<V> use, V x)
{
  const Int<V> fast = use & in_log_range(x);
  V r = lanes::log<kIsa>(select<kIsa>(fast, x, splat<V>(1.0)));
  if (!lanes::all<kIsa>(fast | ~use))
    for (int l = 0; l < kLanesOf<V>; ++l)
      if (use[l] && !fast[l]) r[l] = log_fast(x[l]);
  return r;
}

// gap_forms::aliasing(y, log_fast) where `use`.
template <Isa kIsa, class V>
OHMDEM_LANES_INLINE V aliasing(Int<V> use, V y)
{
  const V e = y - 1.0;
  const Int<V> small = (e < 1e-6) & (e > -1e-6);  // fabs(e) < 1e-6
  const V series = e * (1.0 - e * (0.5 - e * (1.0 / 3.0 - 0.25 * e))) / gap_forms::kQuarter;
  if (lanes::all<kIsa>(small | ~use)) return series;
  return select<kIsa>(small, series, log_where<kIsa>(use & ~small, y) / gap_forms::kQuarter);
}

// erfc_fast's coefficients g_k.
template <class V>
inline constexpr LaneCoefficients<22, V> kErfcLanes = in_lanes<V>(kErfcG);

// erfc_fast where `use`; 0 elsewhere.
template <Isa kIsa, class V>
OHMDEM_LANES_INLINE V erfc_where(Int<V> use, V xm)
{
  const Int<V> fast = use & (xm >= 0.5) & (xm <= 26.0);
  V f = splat<V>(0.0);
  if (lanes::any<kIsa>(fast)) {
    const V x = select<kIsa>(fast, xm, splat<V>(1.0));
    const V t = 2.0 / (2.0 + x), s = 2.0 * t - 1.0;
    const V g = estrin::polynomial<22>(kErfcLanes<V>.c, s);
    f = select<kIsa>(fast, t * lanes::exp<kIsa>(g - x * x), f);
  }
  if (!lanes::all<kIsa>(fast | ~use))
    for (int l = 0; l < kLanesOf<V>; ++l)
      if (use[l] && !fast[l]) f[l] = erfc_fast(xm[l]);
  return f;
}

}  // namespace ohmdem::lubrication::race_lanes

#endif
