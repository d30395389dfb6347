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

// The same with buffers kept from call to call, for styles that reduce at every step: no
// allocation once the buffers have grown, and the order found at the previous call is tried
// first (atoms change their local order only when they are sorted or exchanged).
template <int N>
class OrderedGather {
 public:
  // The records of all ranks in tag order; valid until the next call.
  const std::vector<TaggedValues<N>> &gather(const std::vector<TaggedValues<N>> &local,
                                             MPI_Comm comm);
  std::size_t memory_usage() const;

 private:
  std::vector<TaggedValues<N>> received_;  // several ranks: all records, in rank order
  std::vector<TaggedValues<N>> sorted_;
  std::vector<int> order_;  // sorted_[k] = records[order_[k]]
  std::vector<int> bytes_, displ_;
};

// Sum of each component over all ranks' records, added in tag order.
template <int N>
std::array<double, N> ordered_sum(const std::vector<TaggedValues<N>> &all)
{
  std::array<double, N> s{};
  for (const auto &r : all)
    for (int k = 0; k < N; ++k) s[k] += r.v[k];
  return s;
}

}  // namespace ohmdem

#include "ordered_reduce_impl.h"

#endif
