// SPDX-License-Identifier: GPL-2.0-or-later
// The last few values of a function of a few doubles, looked up by exact key: a kernel
// evaluated for every contact at every step keeps what depends only on a race's constants
// (a bearing has two races). The value is a pure function of the key, so results do not
// depend on the order of the calls (1 and N processes agree bit for bit).
#ifndef OHMDEM_LUBRICATION_KEYED_CACHE_H
#define OHMDEM_LUBRICATION_KEYED_CACHE_H

#include <array>
#include <cstddef>

namespace ohmdem::lubrication {

template <std::size_t K, class Value, std::size_t N = 4>
class KeyedCache {
 public:
  using Key = std::array<double, K>;
  // The value for key, made by make(key) on a miss (a NaN key never hits: made each time).
  template <class Make>
  const Value &get(const Key &key, Make make)
  {
    for (std::size_t i = 0; i < used_; ++i)
      if (keys_[i] == key) return values_[i];
    const std::size_t slot = next_;
    next_ = (next_ + 1) % N;
    if (used_ < N) ++used_;
    keys_[slot] = key;
    values_[slot] = make(key);
    return values_[slot];
  }

 private:
  std::array<Key, N> keys_{};
  std::array<Value, N> values_{};
  std::size_t used_ = 0, next_ = 0;
};

}  // namespace ohmdem::lubrication

#endif
