// SPDX-License-Identifier: GPL-2.0-or-later
// Four or eight doubles per operation (GCC/Clang vector extensions) for the per-contact hot
// loops, and the inline logarithm and exponential of fast_exp_log.h lane by lane (plain C++).
//
// Each function does, in every lane, the same IEEE operations in the same order as its scalar
// model, so a lane's result is bit for bit the scalar one: it does not depend on the lane, on
// the other lanes, on the width or on the instruction set (+ - * / sqrt are correctly
// rounded; no lane is mixed with another). Inputs outside a fast range are not handled here:
// the callers keep such lanes out (a harmless value) and give them to the scalar function.
// The template argument Isa picks how tables are read and masks tested and blended: plain
// code, AVX2's gathers, sign masks and blends (four lanes, only in code compiled for AVX2), or
// AVX-512's mask registers and permutes (eight lanes, only in code compiled for AVX-512F and
// DQ): the same loads and choices, so the same bits.
// tests/lib/lubrication/test_race_admittance_batch.cpp checks the bits.
#ifndef OHMDEM_LANES_H
#define OHMDEM_LANES_H

#include <immintrin.h>  // declares the AVX2 and AVX-512 builtins (used only under their targets)

#include <cmath>
#include <cstdint>

#include "common/fast_exp_log.h"

namespace ohmdem::lanes {

typedef double v4d __attribute__((vector_size(32)));
typedef std::int64_t v4i __attribute__((vector_size(32)));  // also a comparison's mask
typedef std::uint64_t v4u __attribute__((vector_size(32)));
typedef double v8d __attribute__((vector_size(64)));
typedef std::int64_t v8i __attribute__((vector_size(64)));
typedef std::uint64_t v8u __attribute__((vector_size(64)));

// A vector's lane count and its integer forms: Int<V> (also a comparison's mask), Uint<V>.
template <class V>
struct Of;
template <>
struct Of<v4d> {
  static constexpr int kLanes = 4;
  typedef v4i Int;
  typedef v4u Uint;
};
template <>
struct Of<v8d> {
  static constexpr int kLanes = 8;
  typedef v8i Int;
  typedef v8u Uint;
};
template <class V>
using Int = typename Of<V>::Int;
template <class V>
using Uint = typename Of<V>::Uint;
template <class V>
constexpr int kLanesOf = Of<V>::kLanes;

// How a function reads tables and tests and blends masks (see the top).
enum class Isa { plain, avx2, avx512 };

#define OHMDEM_LANES_INLINE inline __attribute__((always_inline))

// x in every lane (constexpr: tables of such vectors need no initializer at run time).
template <class V>
OHMDEM_LANES_INLINE constexpr V splat(double x)
{
  if constexpr (kLanesOf<V> == 4)
    return V{x, x, x, x};
  else
    return V{x, x, x, x, x, x, x, x};
}

// AVX2's and AVX-512's gathers, sign masks, blends and permutes as GCC builtins (the
// intrinsics' wrappers could not be inlined into these plain functions): only in code inlined
// into a function compiled for that set. A gather or a permute loads the same doubles as the
// lane-by-lane loads.
typedef long long v4ll __attribute__((vector_size(32)));
typedef long long v8ll __attribute__((vector_size(64)));
OHMDEM_LANES_INLINE v4d gather_avx2(const double *base, v4i index)
{
  const v4i every = {-1, -1, -1, -1};  // all four lanes loaded
  return __builtin_ia32_gatherdiv4df(v4d{0, 0, 0, 0}, base, (v4ll)index, (v4d)every, 8);
}
OHMDEM_LANES_INLINE unsigned signs(v4i mask)
{
  return __builtin_ia32_movmskpd256((v4d)mask);
}
OHMDEM_LANES_INLINE unsigned signs(v8i mask)
{
  return static_cast<unsigned char>(__builtin_ia32_cvtq2mask512((v8ll)mask));  // AVX-512DQ
}
// t[index[l]] from a table of 32 (index 0-31): two-source permutes of its four rows of eight
// and a blend on the index's bit 4, no memory gather.
OHMDEM_LANES_INLINE v8d table32_avx512(const double *t, v8i index)
{
  v8d row[4];
  __builtin_memcpy(row, t, sizeof row);
  const v8d lo = __builtin_ia32_vpermt2varpd512_mask((v8ll)index, row[0], row[1], -1);
  const v8d hi = __builtin_ia32_vpermt2varpd512_mask((v8ll)index, row[2], row[3], -1);
  const v8ll bit4 = {16, 16, 16, 16, 16, 16, 16, 16};
  return __builtin_ia32_blendmpd_512_mask(lo, hi, __builtin_ia32_ptestmq512((v8ll)index, bit4, -1));
}

// p[0 .. m) into lanes [0, m) of `rest` (0 <= m <= 8), nothing read past them.
OHMDEM_LANES_INLINE v8d load_first(const double *p, int m, v8d rest)
{
  return __builtin_ia32_loadupd512_mask(p, rest, static_cast<unsigned char>((1u << m) - 1));
}
// mask ? a : b, lane by lane (mask lanes all ones or all zeros).
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V select(Int<V> mask, V a, V b)
{
  if constexpr (kIsa == Isa::avx2 && kLanesOf<V> == 4)
    return __builtin_ia32_blendvpd256(b, a, (V)mask);
  else if constexpr (kIsa == Isa::avx512 && kLanesOf<V> == 8)
    return __builtin_ia32_blendmpd_512_mask(b, a, static_cast<unsigned char>(signs(mask)));
  else
    return (V)(((Int<V>)a & mask) | ((Int<V>)b & ~mask));
}
// std::min(a, b) and std::max(a, b) as <algorithm> defines them: (b < a ? b : a), (a < b ? b : a).
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V min(V a, V b)
{
  return select<kIsa>(b < a, b, a);
}
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V max(V a, V b)
{
  return select<kIsa>(a < b, b, a);
}
// base[index[l]] lane by lane.
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V table(const double *base, Int<V> index)
{
  if constexpr (kIsa == Isa::avx2 && kLanesOf<V> == 4) {
    return gather_avx2(base, index);
  } else {
    V r;
    for (int l = 0; l < kLanesOf<V>; ++l) r[l] = base[index[l]];
    return r;
  }
}
// t[index[l]], t a table of 32 (AVX-512: permutes).
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V table32(const double *t, Int<V> index)
{
  if constexpr (kIsa == Isa::avx512 && kLanesOf<V> == 8)
    return table32_avx512(t, index);
  else
    return table<kIsa, V>(t, index);
}
// Whether any or all lanes of a mask (lanes all ones or all zeros) are set.
template <Isa kIsa = Isa::plain, class M>
OHMDEM_LANES_INLINE bool any(M mask)
{
  if constexpr (kIsa != Isa::plain) {
    return signs(mask) != 0;
  } else {
    std::int64_t r = 0;
    for (int l = 0; l < static_cast<int>(sizeof(M) / sizeof(r)); ++l) r |= mask[l];
    return r != 0;
  }
}
template <Isa kIsa = Isa::plain, class M>
OHMDEM_LANES_INLINE bool all(M mask)
{
  constexpr int n = sizeof(M) / sizeof(std::int64_t);
  if constexpr (kIsa != Isa::plain) {
    return signs(mask) == (1u << n) - 1;
  } else {
    std::int64_t r = -1;
    for (int l = 0; l < n; ++l) r &= mask[l];
    return r != 0;
  }
}
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V sqrt(V x)
{
  if constexpr (kIsa == Isa::avx512 && kLanesOf<V> == 8) {
    return __builtin_ia32_sqrtpd512_mask(x, x, -1, 4);  // 4: the current rounding mode
  } else {
    V r;
    for (int l = 0; l < kLanesOf<V>; ++l) r[l] = __builtin_sqrt(x[l]);
    return r;
  }
}

// The flat kLogTable's columns, for table32.
struct LogColumns {
  double c[32], lc[32];
};
inline constexpr LogColumns kLogColumns = [] {
  LogColumns t{};
  for (int i = 0; i < 32; ++i) {
    t.c[i] = fast_exp_log_detail::kLogTable[i][0];
    t.lc[i] = fast_exp_log_detail::kLogTable[i][1];
  }
  return t;
}();

// log_fast for lanes with 2.3e-308 <= x <= 1.7e308.
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V log(V x)
{
  namespace d = fast_exp_log_detail;
  using I = Int<V>;
  using U = Uint<V>;
  constexpr std::uint64_t kBase = 0x3fe6a09e667f3bcdull;
  const U off = (U)x - kBase;
  const I k = (I)off >> 52;
  const V m = (V)((U)x - ((U)k << 52));
  const I slot = (I)((off >> 47) & 31);
  const V c = table32<kIsa, V>(kLogColumns.c, slot);
  const V lc = table32<kIsa, V>(kLogColumns.lc, slot);
  const V s = (m - c) / (m + c), z = s * s;
  const V series = 2.0 * s + 2.0 * s * z * (1.0 / 3 + z * (1.0 / 5 + z * (1.0 / 7)));
  // double(k) through the bits of 1.5 2^52 + k (exact for |k| < 2^51; no vector conversion
  // from int64 below AVX-512).
  const V kd = (V)(k + (I)splat<V>(0x1.8p52)) - 0x1.8p52;
  return kd * d::kLn2Hi + (lc + (series + kd * d::kLn2Lo));
}

// exp_fast for lanes with -708 < x < 709.
template <Isa kIsa = Isa::plain, class V>
OHMDEM_LANES_INLINE V exp(V x)
{
  namespace d = fast_exp_log_detail;
  using I = Int<V>;
  using U = Uint<V>;
  constexpr double kShift = 6755399441055744.0, k32InvLn2 = 46.166241308446828;
  const V shifted = x * k32InvLn2 + kShift;
  const V kd = shifted - kShift;
  const V r = (x - kd * (d::kLn2Hi / 32)) - kd * (d::kLn2Lo / 32);
  const V p =
      r + r * r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120 + r * (1.0 / 720)))));
  // The integer kd from the shifted sum's bits (exact: |kd| < 2^51), as static_cast would.
  const I k = (I)shifted - (I)splat<V>(kShift);
  const V t = table32<kIsa, V>(d::kExp2, k & 31);
  const I q = (k - (k & 31)) >> 5;  // (k - (k & 31)) / 32, exact
  return (V)((U)(t + t * p) + ((U)q << 52));
}

}  // namespace ohmdem::lanes

#endif
