// Sums per-particle contributions over all MPI ranks in particle-tag order, so that the
// result is bitwise the same whatever the domain decomposition (1 or N processes).
// A plain MPI_Allreduce would add partial sums in an order that depends on which rank
// owns which particle.
#ifndef OHMDEM_ORDERED_REDUCE_H
#define OHMDEM_ORDERED_REDUCE_H

#include <mpi.h>

#include <array>
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
std::vector<TaggedValues<N>> gather_by_tag(const std::vector<TaggedValues<N>> &local, MPI_Comm comm);

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
