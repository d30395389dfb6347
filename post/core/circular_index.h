// SPDX-License-Identifier: GPL-2.0-or-later
// The index i taken onto 0..n-1 around a circle (folds, whose bins wrap at the period), also for
// negative i.
#ifndef OHMDEM_POST_CORE_CIRCULAR_INDEX_H
#define OHMDEM_POST_CORE_CIRCULAR_INDEX_H

#include <cstddef>

namespace ohmdem::post {

inline std::size_t circular_index(long i, std::size_t n)
{
  const long m = static_cast<long>(n);
  return static_cast<std::size_t>(((i % m) + m) % m);
}

}  // namespace ohmdem::post

#endif
