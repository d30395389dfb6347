// SPDX-License-Identifier: GPL-2.0-or-later
// A distributed map NodeKey -> value; see key_directory.h.
#include "network/key_directory.h"

namespace ohmdem {

namespace {
// splitmix64's finaliser: keys built from tags (tag << 32 | other) spread evenly over ranks.
std::uint64_t mix(std::uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
}  // namespace

KeyDirectory::KeyDirectory(MPI_Comm comm) : comm_(comm)
{
  MPI_Comm_size(comm_, &size_);
  MPI_Comm_rank(comm_, &rank_);
}

int KeyDirectory::home(Key k) const
{
  return static_cast<int>(mix(k) % static_cast<std::uint64_t>(size_));
}

void KeyDirectory::publish(const std::vector<Entry> &mine)
{
  std::vector<std::vector<Entry>> out(size_);
  for (const Entry &e : mine) out[home(e.first)].push_back(e);
  here_ = exchange_blocks(out, comm_);
  std::sort(here_.begin(), here_.end());
  here_.erase(std::unique(here_.begin(), here_.end(),
                          [](const Entry &a, const Entry &b) { return a.first == b.first; }),
              here_.end());
}

std::vector<std::int64_t> KeyDirectory::lookup(const std::vector<Key> &keys) const
{
  std::vector<std::vector<Key>> ask(size_);
  for (Key k : keys) ask[home(k)].push_back(k);
  std::vector<int> asked_by;
  const std::vector<Key> asked = exchange_blocks(ask, comm_, &asked_by);
  // Each rank answers the questions it received, rank by rank, in the order asked.
  std::vector<std::vector<std::int64_t>> reply(size_);
  std::size_t q = 0;
  for (int r = 0; r < size_; ++r)
    for (int n = 0; n < asked_by[r]; ++n, ++q) {
      auto it = std::lower_bound(here_.begin(), here_.end(), Entry{asked[q], INT64_MIN});
      reply[r].push_back(it != here_.end() && it->first == asked[q] ? it->second : kMissing);
    }
  const std::vector<std::int64_t> answers = exchange_blocks(reply, comm_);
  // The answers come grouped by home rank, each group in the order asked.
  std::vector<std::size_t> next(size_ + 1, 0);
  for (int r = 0; r < size_; ++r) next[r + 1] = next[r] + ask[r].size();
  std::vector<std::int64_t> out(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) out[i] = answers[next[home(keys[i])]++];
  return out;
}

}  // namespace ohmdem
