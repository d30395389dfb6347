// SPDX-License-Identifier: GPL-2.0-or-later
// A polynomial c[0] + c[1] x + ... + c[N-1] x^(N-1) in Estrin's form: halves split at the
// largest power of two below N, each evaluated alike, joined as low + high x^(2^j). The
// operations form a tree of depth ~2 log2(N) instead of Horner's chain of 2(N-1) dependent
// ones: in the lubricated contact's hot loop the dependency chain, not the instruction count,
// sets the time (doc/methods/lubricated_contact.md, "Speed"). One template for double and for
// lanes.h's four- and eight-lane vectors: every lane does the scalar form's operations in its order, so
// the same bits (with FMA contraction off, as the lubricated kernels are built).
#ifndef OHMDEM_ESTRIN_H
#define OHMDEM_ESTRIN_H

#include <type_traits>

namespace ohmdem::estrin {

// powers[j] = x^(2^j), j < the tree's depth (powers_of fills them).
template <int N, class T, class C>
inline __attribute__((always_inline)) T evaluate(const C *c, const T *powers)
{
  static_assert(N >= 1, "a polynomial has a coefficient");
  if constexpr (N == 1) {
    // A vector's coefficients are vectors (one load each, no broadcast; the same values).
    static_assert(std::is_same_v<T, C> || std::is_arithmetic_v<T>,
                  "a vector polynomial's coefficients are vectors");
    return T(c[0]);
  } else {
    constexpr int half = [] {
      int h = 1, j = 0;
      while (2 * h < N) h *= 2, ++j;
      return j;
    }();
    constexpr int h = 1 << half;
    return evaluate<h, T>(c, powers) + evaluate<N - h, T>(c + h, powers) * powers[half];
  }
}

// How many powers x^(2^j) a polynomial of N coefficients reads.
constexpr int depth(int n)
{
  int j = 0;
  while ((1 << j) < n) ++j;
  return j;
}

template <int N, class T>
inline __attribute__((always_inline)) void powers_of(T x, T *powers)
{
  powers[0] = x;
  for (int j = 1; j < depth(N); ++j) powers[j] = powers[j - 1] * powers[j - 1];
}

// c[0] + c[1] x + ... + c[N-1] x^(N-1).
template <int N, class T, class C>
inline __attribute__((always_inline)) T polynomial(const C *c, T x)
{
  T powers[depth(N) > 0 ? depth(N) : 1];
  powers_of<N>(x, powers);
  return evaluate<N, T>(c, powers);
}

}  // namespace ohmdem::estrin

#endif
