// SPDX-License-Identifier: GPL-2.0-or-later
// Sums per-particle contributions over all MPI ranks in particle-tag order, so that the
// result is bitwise the same whatever the domain decomposition (1 or N processes).
// A plain MPI_Allreduce would add partial sums in an order that depends on which rank
// owns which particle.
#ifndef OHMDEM_ORDERED_REDUCE_H
#define OHMDEM_ORDERED_REDUCE_H

#include <mpi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace ohmdem {

template <int N>
struct TaggedValues {
  std::int64_t tag;
  std::array<double, N> v;
};

// Gathers every rank's records on all ranks, sorted by tag, then by value.
template <int N>
std::vector<TaggedValues<N>> gather_by_tag(const std::vector<TaggedValues<N>> &local,
                                           MPI_Comm comm);

// Records of all ranks seen in tag order without being copied: the records as received,
// read through a permutation. Valid until the OrderedGather that made it is called again.
template <int N>
class OrderedView {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = TaggedValues<N>;
    using difference_type = std::ptrdiff_t;
    using pointer = const TaggedValues<N> *;
    using reference = const TaggedValues<N> &;
    iterator(const TaggedValues<N> *base, const int *k) : base_(base), k_(k) {}
    const TaggedValues<N> &operator*() const { return base_[*k_]; }
    const TaggedValues<N> *operator->() const { return base_ + *k_; }
    iterator &operator++()
    {
      ++k_;
      return *this;
    }
    bool operator==(const iterator &o) const { return k_ == o.k_; }
    bool operator!=(const iterator &o) const { return k_ != o.k_; }

   private:
    const TaggedValues<N> *base_;
    const int *k_;
  };
  OrderedView(const TaggedValues<N> *base, const int *order, std::size_t n)
      : base_(base), order_(order), n_(n)
  {
  }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const TaggedValues<N> &operator[](std::size_t k) const { return base_[order_[k]]; }
  iterator begin() const { return {base_, order_}; }
  iterator end() const { return {base_, order_ + n_}; }

 private:
  const TaggedValues<N> *base_;
  const int *order_;
  std::size_t n_;
};

// The same with buffers kept from call to call, for styles that reduce at every step: no
// allocation once the buffers have grown, no copy of the records (a view through their tag
// order), and the order found at the previous call is tried first (atoms change their local
// order only when they are sorted or exchanged).
template <int N>
class OrderedGather {
 public:
  // The records of all ranks in tag order; `local` must outlive the view.
  OrderedView<N> gather(const std::vector<TaggedValues<N>> &local, MPI_Comm comm);
  std::size_t memory_usage() const;

 private:
  std::vector<TaggedValues<N>> received_;  // several ranks: all records, in rank order
  std::vector<int> order_;                 // view[k] = records[order_[k]]
  std::vector<int> bytes_, displ_;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int nprocs_ = 1;
};

// Sum of each component over all ranks' records (a vector or a view in tag order), added in
// that order.
template <int N, class Records>
std::array<double, N> ordered_sum(const Records &all)
{
  std::array<double, N> s{};
  for (const TaggedValues<N> &r : all)
    for (int k = 0; k < N; ++k) s[k] += r.v[k];
  return s;
}

}  // namespace ohmdem

#include "common/ordered_reduce_impl.h"

#endif
