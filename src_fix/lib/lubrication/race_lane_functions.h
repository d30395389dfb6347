// SPDX-License-Identifier: GPL-2.0-or-later
// The four-lane forms of race_admittance.cpp's helpers for the batched kernel
// (race_admittance_batch.cpp, its only includer, which is compiled with -ffp-contract=off and
// -fno-math-errno): log_fast's range test, exp_small, gap_forms' form mean and aliasing term,
// log_fast and erfc_fast where a mask asks for them. Each lane does the scalar function's
// operations in its order (the same bits); kAvx2 picks lanes4.h's AVX2 forms.
#ifndef OHMDEM_LUBRICATION_RACE_LANE_FUNCTIONS_H
#define OHMDEM_LUBRICATION_RACE_LANE_FUNCTIONS_H

#include "common/estrin.h"
#include "common/fast_erfc.h"
#include "common/fast_exp_log.h"
#include "common/lanes4.h"
#include "lubrication/exp_small.h"
#include "lubrication/gap_forms.h"

namespace ohmdem::lubrication::race_lanes {

using lanes::kLanes;
using lanes::select;
using lanes::splat;
using lanes::v4d;
using lanes::v4i;

OHMDEM_LANES_INLINE v4i in_log_range(v4d x)
{
  return (x >= 2.3e-308) & (x <= 1.7e308);  // log_fast's
}

// A polynomial's coefficients, each in four lanes: a vector operand of each operation (no
// broadcast per term; the same values, so the same bits).
template <int N>
struct LaneCoefficients {
  v4d c[N];
};
template <int N>
LaneCoefficients<N> in_lanes(const double (&c)[N])
{
  LaneCoefficients<N> t{};
  for (int k = 0; k < N; ++k) t.c[k] = splat(c[k]);
  return t;
}

// exp_small.h's exp_small.
inline const LaneCoefficients<14> kExpSmallLanes = in_lanes(kExpSmall);
OHMDEM_LANES_INLINE v4d exp_small(v4d z)
{
  return 1.0 + z * estrin::polynomial<13>(kExpSmallLanes.c + 1, z);
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

// erfc_fast's coefficients g_k.
inline const LaneCoefficients<22> kErfcLanes = in_lanes(kErfcG);

// erfc_fast where `use`; 0 elsewhere.
template <bool kAvx2>
OHMDEM_LANES_INLINE v4d erfc_where(v4i use, v4d xm)
{
  const v4i fast = use & (xm >= 0.5) & (xm <= 26.0);
  v4d f = splat(0.0);
  if (lanes::any<kAvx2>(fast)) {
    const v4d x = select<kAvx2>(fast, xm, splat(1.0));
    const v4d t = 2.0 / (2.0 + x), s = 2.0 * t - 1.0;
    const v4d g = estrin::polynomial<22>(kErfcLanes.c, s);
    f = select<kAvx2>(fast, t * lanes::exp<kAvx2>(g - x * x), f);
  }
  if (!lanes::all<kAvx2>(fast | ~use))
    for (int l = 0; l < kLanes; ++l)
      if (use[l] && !fast[l]) f[l] = erfc_fast(xm[l]);
  return f;
}

}  // namespace ohmdem::lubrication::race_lanes

#endif
