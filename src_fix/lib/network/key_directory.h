// SPDX-License-Identifier: GPL-2.0-or-later
// A distributed map NodeKey -> 64-bit value over an MPI communicator, for the distributed
// network solve: no rank holds every key. Key k lives on rank home(k) (a hash of k modulo
// the number of ranks); the ranks that own keys publish them there, the ranks that need them
// ask there. Two all-to-all exchanges per publish or lookup, each rank sending and receiving
// only the keys it has or asks for. Deterministic: the answers do not depend on message order.
// Plain C++ with MPI (no LIGGGHTS types).
#ifndef OHMDEM_KEY_DIRECTORY_H
#define OHMDEM_KEY_DIRECTORY_H

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ohmdem {

class KeyDirectory {
 public:
  using Key = std::uint64_t;
  using Entry = std::pair<Key, std::int64_t>;
  static constexpr std::int64_t kMissing = INT64_MIN;

  KeyDirectory() = default;  // empty, on no communicator: assign one before use
  explicit KeyDirectory(MPI_Comm comm);
  // Collective. Replaces the map by the union of every rank's entries (keys should be unique
  // over all ranks; a key published twice keeps the smaller value, so the map stays defined).
  void publish(const std::vector<Entry> &mine);
  // Collective. The value of each key asked for; kMissing for a key nobody published.
  std::vector<std::int64_t> lookup(const std::vector<Key> &keys) const;
  int home(Key k) const;
  std::size_t stored() const { return here_.size(); }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int size_ = 1, rank_ = 0;
  std::vector<Entry> here_;  // the keys whose home is this rank, sorted
};

// All-to-all of variable-length blocks of trivially copyable T: out[r] goes to rank r;
// returns what every rank sent to this one, in rank order (so the order is deterministic).
template <class T>
std::vector<T> exchange_blocks(const std::vector<std::vector<T>> &out, MPI_Comm comm,
                               std::vector<int> *counts_in = nullptr)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> scount(size), rcount(size), sdisp(size + 1, 0), rdisp(size + 1, 0);
  for (int r = 0; r < size; ++r) {
    const std::size_t bytes = out[r].size() * sizeof(T);
    if (bytes > static_cast<std::size_t>(INT_MAX))
      throw std::length_error("distributed network: one message would exceed 2 GB");
    scount[r] = static_cast<int>(bytes);
  }
  MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r) {
    sdisp[r + 1] = sdisp[r] + scount[r];
    rdisp[r + 1] = rdisp[r] + rcount[r];
  }
  std::vector<char> sbuf(static_cast<std::size_t>(sdisp[size]) + 1);
  for (int r = 0; r < size; ++r)
    if (scount[r])
      std::copy_n(reinterpret_cast<const char *>(out[r].data()), scount[r], &sbuf[sdisp[r]]);
  std::vector<T> in(static_cast<std::size_t>(rdisp[size]) / sizeof(T) + 1);
  MPI_Alltoallv(sbuf.data(), scount.data(), sdisp.data(), MPI_BYTE, in.data(), rcount.data(),
                rdisp.data(), MPI_BYTE, comm);
  in.pop_back();
  if (counts_in) {
    counts_in->resize(size);
    for (int r = 0; r < size; ++r) (*counts_in)[r] = rcount[r] / static_cast<int>(sizeof(T));
  }
  return in;
}

}  // namespace ohmdem

#endif
