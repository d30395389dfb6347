// Template implementation of ordered_reduce.h (kept apart so the header reads as an API).
#ifndef OHMDEM_ORDERED_REDUCE_IMPL_H
#define OHMDEM_ORDERED_REDUCE_IMPL_H

#include <algorithm>

namespace ohmdem {

template <int N>
std::vector<TaggedValues<N>> gather_by_tag(const std::vector<TaggedValues<N>> &local, MPI_Comm comm)
{
  static_assert(sizeof(TaggedValues<N>) == sizeof(std::int64_t) + N * sizeof(double),
                "TaggedValues must be packed to be sent as bytes");
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  // Ties (several records of one particle) are ordered by their values, so that the order
  // never depends on which process sent what.
  auto by_tag = [](const TaggedValues<N> &a, const TaggedValues<N> &b) {
    return a.tag != b.tag ? a.tag < b.tag : a.v < b.v;
  };
  if (nprocs == 1) {  // one rank: no collective needed, same order as with several
    std::vector<TaggedValues<N>> all(local);
    std::sort(all.begin(), all.end(), by_tag);
    return all;
  }
  const int mybytes = static_cast<int>(local.size() * sizeof(TaggedValues<N>));
  std::vector<int> bytes(nprocs), displ(nprocs, 0);
  MPI_Allgather(&mybytes, 1, MPI_INT, bytes.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int p = 0; p < nprocs; ++p) {
    displ[p] = total;
    total += bytes[p];
  }
  std::vector<TaggedValues<N>> all(total / sizeof(TaggedValues<N>));
  MPI_Allgatherv(local.data(), mybytes, MPI_BYTE, all.data(), bytes.data(), displ.data(),
                 MPI_BYTE, comm);
  std::sort(all.begin(), all.end(), by_tag);
  return all;
}

}  // namespace ohmdem

#endif
