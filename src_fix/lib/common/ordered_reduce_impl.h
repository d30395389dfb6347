// SPDX-License-Identifier: GPL-2.0-or-later
// Template implementation of ordered_reduce.h (kept apart so the header reads as an API).
#ifndef OHMDEM_ORDERED_REDUCE_IMPL_H
#define OHMDEM_ORDERED_REDUCE_IMPL_H

#include <algorithm>
#include <numeric>

namespace ohmdem {

template <int N>
OrderedView<N> OrderedGather<N>::gather(const std::vector<TaggedValues<N>> &local, MPI_Comm comm)
{
  static_assert(sizeof(TaggedValues<N>) == sizeof(std::int64_t) + N * sizeof(double),
                "TaggedValues must be packed to be sent as bytes");
  if (comm != comm_) {  // asked once per communicator: this runs at every step
    MPI_Comm_size(comm, &nprocs_);
    comm_ = comm;
  }
  const int nprocs = nprocs_;
  const std::vector<TaggedValues<N>> *records = &local;  // one rank: no collective needed
  if (nprocs > 1) {
    const int mybytes = static_cast<int>(local.size() * sizeof(TaggedValues<N>));
    bytes_.resize(nprocs);
    displ_.resize(nprocs);
    MPI_Allgather(&mybytes, 1, MPI_INT, bytes_.data(), 1, MPI_INT, comm);
    int total = 0;
    for (int p = 0; p < nprocs; ++p) {
      displ_[p] = total;
      total += bytes_[p];
    }
    received_.resize(total / sizeof(TaggedValues<N>));
    MPI_Allgatherv(local.data(), mybytes, MPI_BYTE, received_.data(), bytes_.data(), displ_.data(),
                   MPI_BYTE, comm);
    records = &received_;
  }
  const auto &in = *records;
  // Ties (several records of one particle) are ordered by their values, so that the order
  // never depends on which process sent what; records that tie completely are identical.
  auto before = [&in](int a, int b) {
    return in[a].tag != in[b].tag ? in[a].tag < in[b].tag : in[a].v < in[b].v;
  };
  // The previous order still holds if the tags it visits strictly increase (the usual case:
  // one record per particle); otherwise sort again. Sorting indices moves 4 bytes instead of
  // a whole record.
  auto still_sorted = [&] {
    if (order_.size() != in.size()) return false;
    for (std::size_t k = 1; k < order_.size(); ++k)
      if (!(in[order_[k - 1]].tag < in[order_[k]].tag))
        return std::is_sorted(order_.begin(), order_.end(), before);
    return true;
  };
  if (!still_sorted()) {
    order_.resize(in.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(), before);
  }
  return OrderedView<N>(in.data(), order_.data(), in.size());
}

template <int N>
std::size_t OrderedGather<N>::memory_usage() const
{
  return received_.capacity() * sizeof(TaggedValues<N>) +
         (order_.capacity() + bytes_.capacity() + displ_.capacity()) * sizeof(int);
}

template <int N>
std::vector<TaggedValues<N>> gather_by_tag(const std::vector<TaggedValues<N>> &local, MPI_Comm comm)
{
  OrderedGather<N> gather;
  const OrderedView<N> view = gather.gather(local, comm);
  return std::vector<TaggedValues<N>>(view.begin(), view.end());
}

}  // namespace ohmdem

#endif
