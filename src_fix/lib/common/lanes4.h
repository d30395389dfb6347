// SPDX-License-Identifier: GPL-2.0-or-later
// Four doubles per operation (GCC/Clang vector extensions) for the per-contact hot loops, and
// the inline logarithm, exponential and cube root of fast_exp_log.h and fast_cbrt.h lane by
// lane (plain C++).
//
// Each function does, in every lane, the same IEEE operations in the same order as its scalar
// model, so a lane's result is bit for bit the scalar one: it does not depend on the lane, on
// the other lanes or on the instruction set (+ - * / sqrt are correctly rounded; no lane is
// mixed with another). Inputs outside a fast range are not handled here: the callers keep
// such lanes out (a harmless value) and give them to the scalar function. A template argument
// kAvx2 = true (only in code compiled for AVX2) reads tables with gathers and tests and blends
// masks in one instruction each: the same loads and choices, so the same bits.
// tests/lib/lubrication/test_race_admittance_batch.cpp checks the bits.
#ifndef OHMDEM_LANES4_H
#define OHMDEM_LANES4_H

#include <immintrin.h>  // declares the AVX2 builtins (used only under target("avx2"))

#include <cmath>
#include <cstdint>

#include "common/fast_exp_log.h"

namespace ohmdem::lanes {

constexpr int kLanes = 4;
typedef double v4d __attribute__((vector_size(32)));
typedef std::int64_t v4i __attribute__((vector_size(32)));  // also a comparison's mask
typedef std::uint64_t v4u __attribute__((vector_size(32)));

#define OHMDEM_LANES_INLINE inline __attribute__((always_inline))

OHMDEM_LANES_INLINE v4d splat(double x)
{
  return v4d{x, x, x, x};
}
// AVX2's gather and AVX's sign mask, as GCC builtins: only in code inlined into a function
// compiled for AVX2 (the template argument kAvx2 of the functions below chooses them; their
// default is plain code). A gather loads the same doubles as the lane-by-lane loads.
typedef long long v4ll __attribute__((vector_size(32)));
OHMDEM_LANES_INLINE v4d gather_avx2(const double *base, v4i index)
{
  const v4i every = {-1, -1, -1, -1};  // all four lanes loaded
  return __builtin_ia32_gatherdiv4df(v4d{0, 0, 0, 0}, base, (v4ll)index, (v4d)every, 8);
}
OHMDEM_LANES_INLINE int signs_avx2(v4i mask)
{
  return __builtin_ia32_movmskpd256((v4d)mask);
}
// mask ? a : b, lane by lane (mask lanes all ones or all zeros); kAvx2: one blend.
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d select(v4i mask, v4d a, v4d b)
{
  if constexpr (kAvx2)
    return __builtin_ia32_blendvpd256(b, a, (v4d)mask);
  else
    return (v4d)(((v4i)a & mask) | ((v4i)b & ~mask));
}
// std::min(a, b) and std::max(a, b) as <algorithm> defines them: (b < a ? b : a), (a < b ? b : a).
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d min(v4d a, v4d b)
{
  return select<kAvx2>(b < a, b, a);
}
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d max(v4d a, v4d b)
{
  return select<kAvx2>(a < b, b, a);
}
// base[index[l]] lane by lane.
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d table(const double *base, v4i index)
{
  if constexpr (kAvx2) {
    return gather_avx2(base, index);
  } else {
    v4d r;
    for (int l = 0; l < kLanes; ++l) r[l] = base[index[l]];
    return r;
  }
}
// Whether any or all lanes of a mask (lanes all ones or all zeros) are set.
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE bool any(v4i mask)
{
  if constexpr (kAvx2)
    return signs_avx2(mask) != 0;
  else
    return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
}
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE bool all(v4i mask)
{
  if constexpr (kAvx2)
    return signs_avx2(mask) == 15;
  else
    return (mask[0] & mask[1] & mask[2] & mask[3]) != 0;
}
OHMDEM_LANES_INLINE v4d sqrt(v4d x)
{
  v4d r;
  for (int l = 0; l < kLanes; ++l) r[l] = __builtin_sqrt(x[l]);
  return r;
}

// log_fast for lanes with 2.3e-308 <= x <= 1.7e308.
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d log(v4d x)
{
  namespace d = fast_exp_log_detail;
  constexpr std::uint64_t kBase = 0x3fe6a09e667f3bcdull;
  const v4u off = (v4u)x - kBase;
  const v4i k = (v4i)off >> 52;
  const v4d m = (v4d)((v4u)x - ((v4u)k << 52));
  const v4i row = (v4i)(((off >> 47) & 31) << 1);  // kLogTable[slot] as a flat index
  const v4d c = table<kAvx2>(&d::kLogTable[0][0], row);
  const v4d lc = table<kAvx2>(&d::kLogTable[0][0] + 1, row);
  const v4d s = (m - c) / (m + c), z = s * s;
  const v4d series = 2.0 * s + 2.0 * s * z * (1.0 / 3 + z * (1.0 / 5 + z * (1.0 / 7)));
  // double(k) through the bits of 1.5 2^52 + k (exact for |k| < 2^51; no vector conversion
  // from int64 below AVX-512).
  const v4d kd = (v4d)(k + (v4i)splat(0x1.8p52)) - 0x1.8p52;
  return kd * d::kLn2Hi + (lc + (series + kd * d::kLn2Lo));
}

// exp_fast for lanes with -708 < x < 709.
template <bool kAvx2 = false>
OHMDEM_LANES_INLINE v4d exp(v4d x)
{
  namespace d = fast_exp_log_detail;
  constexpr double kShift = 6755399441055744.0, k32InvLn2 = 46.166241308446828;
  const v4d shifted = x * k32InvLn2 + kShift;
  const v4d kd = shifted - kShift;
  const v4d r = (x - kd * (d::kLn2Hi / 32)) - kd * (d::kLn2Lo / 32);
  const v4d p =
      r + r * r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720)))));
  // The integer kd from the shifted sum's bits (exact: |kd| < 2^51), as static_cast would.
  const v4i k = (v4i)shifted - (v4i)splat(kShift);
  const v4d t = table<kAvx2>(d::kExp2, k & 31);
  const v4i q = (k - (k & 31)) >> 5;  // (k - (k & 31)) / 32, exact
  return (v4d)((v4u)(t + t * p) + ((v4u)q << 52));
}

// cbrt_fast for lanes with 2.3e-308 <= x <= 1e300.
OHMDEM_LANES_INLINE v4d cbrt(v4d x)
{
  v4u bits = (v4u)x;
  for (int l = 0; l < kLanes; ++l) bits[l] = bits[l] / 3 + 0x2A9F7893782DA1CEull;
  v4d y = (v4d)bits;
  v4d y3 = y * y * y;
  y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  y3 = y * y * y;
  y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  return y + (x / (y * y) - y) * (1.0 / 3.0);
}

}  // namespace ohmdem::lanes

#endif
