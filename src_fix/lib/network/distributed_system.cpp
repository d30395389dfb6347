// SPDX-License-Identifier: GPL-2.0-or-later
// The distributed Kirchhoff system; see distributed_system.h.
#include "network/distributed_system.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "network/key_directory.h"

namespace ohmdem {

namespace {

constexpr int kHigh = -1, kLow = -2;  // column of an electrode in a routed entry
constexpr int kUnknown = -3;          // not yet looked up
constexpr int kSkip = -4;             // an edge that adds no entry (ignored, loop, direct)

using Entry = DistributedEntry;

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t find(std::size_t i)
  {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  // The smaller index becomes the root: the labels do not depend on the order of unions.
  void unite(std::size_t a, std::size_t b)
  {
    a = find(a), b = find(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::size_t> parent_;
};

template <class T>
std::vector<T> gather_to_root(const std::vector<T> &mine, MPI_Comm comm, std::vector<int> &counts)
{
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  const int bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> rb(size), disp(size + 1, 0);
  MPI_Gather(&bytes, 1, MPI_INT, rb.data(), 1, MPI_INT, 0, comm);
  for (int r = 0; r < size; ++r) disp[r + 1] = disp[r] + rb[r];
  std::vector<T> all(rank == 0 ? static_cast<std::size_t>(disp[size]) / sizeof(T) + 1 : 1);
  MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), rb.data(), disp.data(), MPI_BYTE, 0, comm);
  all.pop_back();
  counts.resize(size);
  for (int r = 0; r < size; ++r) counts[r] = rb[r] / static_cast<int>(sizeof(T));
  return all;
}

// Sorted entries -> compressed rows with the diagonal, the right-hand side and the flags of
// the electrodes each row touches (bit 0 high, bit 1 low).
void build_rows(const std::vector<Entry> &in, int n, int first, DistributedSystem &s,
                std::vector<unsigned char> &touches)
{
  s.row_start.assign(1, 0);
  s.columns.clear();
  s.values.clear();
  s.rhs.assign(n, 0.0);
  s.to_low.assign(n, 0.0);
  touches.assign(n, 0);
  std::size_t p = 0;
  for (int i = 0; i < n; ++i) {
    const int row = first + i;
    double diag = 0.0;
    const std::size_t begin = p;
    while (p < in.size() && in[p].row == row) diag += in[p++].g;
    bool placed = false;
    for (std::size_t k = begin; k < p;) {
      const int col = in[k].col;
      double sum = 0.0;
      for (; k < p && in[k].col == col; ++k) sum += in[k].g;
      if (col == kHigh) {
        s.rhs[i] = sum;
        touches[i] |= 1;
        continue;
      }
      if (col == kLow) {
        s.to_low[i] = sum;
        touches[i] |= 2;
        continue;
      }
      if (!placed && col > row) {
        s.columns.push_back(row), s.values.push_back(diag);
        placed = true;
      }
      s.columns.push_back(col), s.values.push_back(-sum);
    }
    if (!placed) s.columns.push_back(row), s.values.push_back(diag);
    s.row_start.push_back(static_cast<int>(s.columns.size()));
  }
}

// Floating components (see the header): marks their rows and makes them identity rows.
void mark_floating(MPI_Comm comm, int n, int first, const std::vector<unsigned char> &touches,
                   DistributedSystem &s)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // Local union-find over the owned rows and the ghost columns.
  std::vector<int> ghosts;
  for (int c : s.columns)
    if (c < first || c >= first + n) ghosts.push_back(c);
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  auto local = [&](int c) -> std::size_t {
    if (c >= first && c < first + n) return static_cast<std::size_t>(c - first);
    return n + static_cast<std::size_t>(std::lower_bound(ghosts.begin(), ghosts.end(), c) -
                                        ghosts.begin());
  };
  UnionFind uf(n + ghosts.size());
  for (int i = 0; i < n; ++i)
    for (int k = s.row_start[i]; k < s.row_start[i + 1]; ++k) uf.unite(i, local(s.columns[k]));
  // Components numbered by their first row; their electrode flags.
  std::vector<int> comp_of_root(n + ghosts.size(), -1), label(n);
  std::vector<unsigned char> flags;
  for (int i = 0; i < n; ++i) {
    int &c = comp_of_root[uf.find(i)];
    if (c < 0) c = static_cast<int>(flags.size()), flags.push_back(0);
    label[i] = c;
    flags[c] |= touches[i];
  }
  long long ncomp = static_cast<long long>(flags.size()), offset = 0;
  MPI_Exscan(&ncomp, &offset, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) offset = 0;
  // The cross-rank edges in terms of components: (row, its component) for the boundary rows,
  // (component, ghost row) for every ghost neighbour. Edges reach both owners, so the ghost
  // row is a boundary row of its owner.
  struct RowLabel {
    long long label;
    int row;
  };
  std::vector<RowLabel> boundary, cross;
  for (int i = 0; i < n; ++i) {
    bool any = false;
    for (int k = s.row_start[i]; k < s.row_start[i + 1]; ++k) {
      const int c = s.columns[k];
      if (c >= first && c < first + n) continue;
      cross.push_back({offset + label[i], c});
      any = true;
    }
    if (any) boundary.push_back({offset + label[i], first + i});
  }
  std::vector<int> nflags, nb, nc;
  const auto all_flags = gather_to_root(flags, comm, nflags);
  auto all_boundary = gather_to_root(boundary, comm, nb);
  const auto all_cross = gather_to_root(cross, comm, nc);
  std::vector<unsigned char> grounded;  // rank 0: per component, 1 if it reaches an electrode
  int connected = 0;
  if (rank == 0) {
    UnionFind global(all_flags.size());
    std::sort(all_boundary.begin(), all_boundary.end(),
              [](const RowLabel &a, const RowLabel &b) { return a.row < b.row; });
    for (const RowLabel &x : all_cross) {
      auto it = std::lower_bound(all_boundary.begin(), all_boundary.end(), x.row,
                                 [](const RowLabel &a, int r) { return a.row < r; });
      if (it == all_boundary.end() || it->row != x.row)
        throw std::logic_error("distributed network: an edge is known to one owner only");
      global.unite(static_cast<std::size_t>(x.label), static_cast<std::size_t>(it->label));
    }
    std::vector<unsigned char> root_flags(all_flags.size(), 0);
    for (std::size_t c = 0; c < all_flags.size(); ++c) root_flags[global.find(c)] |= all_flags[c];
    grounded.resize(all_flags.size());
    for (std::size_t c = 0; c < all_flags.size(); ++c) {
      const unsigned char f = root_flags[global.find(c)];
      grounded[c] = f != 0;
      if (f == 3) connected = 1;
    }
  }
  MPI_Bcast(&connected, 1, MPI_INT, 0, comm);
  std::vector<int> disp(nflags.size() + 1, 0);
  for (std::size_t r = 0; r < nflags.size(); ++r) disp[r + 1] = disp[r] + nflags[r];
  std::vector<unsigned char> mine(flags.size() + 1);
  MPI_Scatterv(grounded.data(), nflags.data(), disp.data(), MPI_UNSIGNED_CHAR, mine.data(),
               static_cast<int>(flags.size()), MPI_UNSIGNED_CHAR, 0, comm);
  s.connected = connected != 0 || s.direct > 0.0;
  // Floating rows -> identity rows (their neighbours are floating too: symmetry is kept).
  s.floating.assign(n, 0);
  long long nfloat = 0;
  for (int i = 0; i < n; ++i) nfloat += !mine[label[i]];
  if (nfloat == 0) {  // the common case: the rows stay as they are
    MPI_Allreduce(&nfloat, &s.floating_rows, 1, MPI_LONG_LONG, MPI_SUM, comm);
    s.ghosts = std::move(ghosts);
    return;
  }
  nfloat = 0;
  std::vector<int> start{0};
  std::vector<int> cols;
  std::vector<double> vals;
  for (int i = 0; i < n; ++i) {
    if (!mine[label[i]]) {
      s.floating[i] = 1;
      ++nfloat;
      cols.push_back(first + i), vals.push_back(1.0);
      s.rhs[i] = 0.0;
      s.to_low[i] = 0.0;
    } else {
      cols.insert(cols.end(), s.columns.begin() + s.row_start[i],
                  s.columns.begin() + s.row_start[i + 1]);
      vals.insert(vals.end(), s.values.begin() + s.row_start[i],
                  s.values.begin() + s.row_start[i + 1]);
    }
    start.push_back(static_cast<int>(cols.size()));
  }
  s.row_start.swap(start);
  s.columns.swap(cols);
  s.values.swap(vals);
  MPI_Allreduce(&nfloat, &s.floating_rows, 1, MPI_LONG_LONG, MPI_SUM, comm);
  s.ghosts.clear();
  for (int c : s.columns)
    if (c < first || c >= first + n) s.ghosts.push_back(c);
  std::sort(s.ghosts.begin(), s.ghosts.end());
  s.ghosts.erase(std::unique(s.ghosts.begin(), s.ghosts.end()), s.ghosts.end());
}

}  // namespace

std::vector<double> values_at_rows(MPI_Comm comm, const DistributedSystem &s,
                                   const std::vector<double> &mine, const std::vector<int> &rows)
{
  const int size = static_cast<int>(s.starts.size()) - 1;
  std::vector<std::vector<int>> ask(size);
  for (int g : rows) {
    const int r =
        static_cast<int>(std::upper_bound(s.starts.begin(), s.starts.end(), g) - s.starts.begin()) -
        1;
    ask[r].push_back(g);
  }
  std::vector<int> asked_by;
  const std::vector<int> asked = exchange_blocks(ask, comm, &asked_by);
  std::vector<std::vector<double>> reply(size);
  std::size_t q = 0;
  for (int r = 0; r < size; ++r)
    for (int k = 0; k < asked_by[r]; ++k, ++q) reply[r].push_back(mine[asked[q] - s.first_row]);
  // Rows are sorted and ranks own increasing ranges: the answers come back in row order.
  return exchange_blocks(reply, comm);
}

double ordered_rank_sum(double mine, MPI_Comm comm)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<double> all(size);
  MPI_Allgather(&mine, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, comm);
  double sum = 0.0;
  for (double v : all) sum += v;
  return sum;
}

void assemble_distributed(MPI_Comm comm, std::vector<NodeKey> owned,
                          const std::vector<DistributedEdge> &edges, NodeKey high, NodeKey low,
                          DistributedSystem &s)
{
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::sort(owned.begin(), owned.end());
  owned.erase(std::unique(owned.begin(), owned.end()), owned.end());
  owned.erase(
      std::remove_if(owned.begin(), owned.end(), [&](NodeKey k) { return k == high || k == low; }),
      owned.end());
  // Contiguous rows per rank, in rank order.
  long long n = static_cast<long long>(owned.size()), first = 0, total = 0;
  MPI_Exscan(&n, &first, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (rank == 0) first = 0;
  MPI_Allreduce(&n, &total, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if (total >= INT_MAX)
    throw std::length_error("distributed network: more than 2^31 - 1 nodes (hypre's indices)");
  s.first_row = static_cast<int>(first);
  s.total_rows = static_cast<int>(total);
  s.keys = std::move(owned);
  std::vector<int> starts(size + 1);
  const int my_first = s.first_row;
  MPI_Allgather(&my_first, 1, MPI_INT, starts.data(), 1, MPI_INT, comm);
  starts[size] = s.total_rows;
  s.starts = starts;
  auto owner = [&](int row) {
    return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), row) - starts.begin()) -
           1;
  };

  // Rows of the edges' ends, from the directory.
  s.directory = KeyDirectory(comm);
  KeyDirectory &dir = s.directory;
  {
    std::vector<KeyDirectory::Entry> mine(s.keys.size());
    for (std::size_t i = 0; i < s.keys.size(); ++i)
      mine[i] = {s.keys[i], my_first + static_cast<long long>(i)};
    dir.publish(mine);
  }
  // The rows of the edges' ends: most are this rank's own nodes (a hash map), the others are
  // asked of the directory.
  std::unordered_map<NodeKey, int> own;
  own.reserve(s.keys.size() * 2);
  for (std::size_t i = 0; i < s.keys.size(); ++i)
    own.emplace(s.keys[i], my_first + static_cast<int>(i));
  DistributedScratch &w = s.scratch;
  std::vector<int> &ends = w.ends;
  ends.resize(2 * edges.size());
  std::vector<NodeKey> &need = w.need;
  need.clear();
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (int side = 0; side < 2; ++side) {
      const NodeKey k = side ? edges[e].b : edges[e].a;
      int &r = ends[2 * e + side];
      if (k == high) {
        r = kHigh;
      } else if (k == low) {
        r = kLow;
      } else {
        auto it = own.find(k);
        r = it != own.end() ? it->second : kUnknown;
        if (r == kUnknown) need.push_back(k);
      }
    }
  std::sort(need.begin(), need.end());
  need.erase(std::unique(need.begin(), need.end()), need.end());
  const std::vector<std::int64_t> rows = dir.lookup(need);
  int missing = 0;
  for (std::int64_t r : rows) missing |= r == KeyDirectory::kMissing;
  MPI_Allreduce(MPI_IN_PLACE, &missing, 1, MPI_INT, MPI_MAX, comm);
  if (missing)
    throw std::invalid_argument("distributed network: an edge names a node that no rank owns");
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (int side = 0; side < 2; ++side) {
      int &r = ends[2 * e + side];
      if (r != kUnknown) continue;
      const NodeKey k = side ? edges[e].b : edges[e].a;
      r = static_cast<int>(rows[std::lower_bound(need.begin(), need.end(), k) - need.begin()]);
    }

  // Each edge to the owners of both ends. This rank's own rows are counted in a first pass
  // over the edges and placed in a second, straight into their row's range (no list of
  // entries in between); the others' go out, and what comes in is placed after them.
  std::vector<std::vector<Entry>> &out = w.outgoing;
  out.resize(size);
  for (auto &o : out) o.clear();
  std::vector<std::size_t> &at = w.bucket;
  at.assign(static_cast<std::size_t>(n) + 1, 0);
  auto here = [&](int r) { return r >= my_first && r < my_first + n; };
  long long accepted = 0, ignored = 0, loops = 0;
  double direct = 0.0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const DistributedEdge &e = edges[k];
    int &ra = ends[2 * k], &rb = ends[2 * k + 1];
    if (!(e.g > 0.0) || !std::isfinite(e.g)) {
      ++ignored;
      ra = rb = kSkip;
      continue;
    }
    if (e.a == e.b) {
      ++loops;
      ra = rb = kSkip;
      continue;
    }
    ++accepted;
    if (ra < 0 && rb < 0) {
      direct += e.g;
      ra = rb = kSkip;
      continue;
    }
    for (const auto &[row, col] : {std::pair<int, int>{ra, rb}, std::pair<int, int>{rb, ra}}) {
      if (row < 0) continue;  // an electrode: no row
      if (here(row))
        ++at[row - my_first + 1];
      else
        out[owner(row)].push_back({row, col, e.g});
    }
  }
  // Received in rank order; the order of arrival does not matter (rows are sorted below).
  const std::vector<Entry> received = exchange_blocks(out, comm);
  for (const Entry &x : received) ++at[x.row - my_first + 1];
  for (long long i = 0; i < n; ++i) at[i + 1] += at[i];
  std::vector<Entry> &sorted = w.sorted;
  sorted.resize(at[n]);
  {
    std::vector<std::size_t> next(at.begin(), at.end() - 1);
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const int ra = ends[2 * k], rb = ends[2 * k + 1];
      if (ra == kSkip) continue;
      if (ra >= 0 && here(ra)) sorted[next[ra - my_first]++] = {ra, rb, edges[k].g};
      if (rb >= 0 && here(rb)) sorted[next[rb - my_first]++] = {rb, ra, edges[k].g};
    }
    for (const Entry &x : received) sorted[next[x.row - my_first]++] = x;
  }
  // Each row's few entries sorted by (column, g): the sums below do not depend on the order
  // of arrival.
  for (long long i = 0; i < n; ++i)
    std::sort(sorted.begin() + at[i], sorted.begin() + at[i + 1],
              [](const Entry &x, const Entry &y) {
                return std::tie(x.col, x.g) < std::tie(y.col, y.g);
              });
  long long counts[3] = {accepted, ignored, loops}, sums[3];
  MPI_Allreduce(counts, sums, 3, MPI_LONG_LONG, MPI_SUM, comm);
  s.edges = sums[0], s.ignored = sums[1], s.self_loops = sums[2];
  s.direct = ordered_rank_sum(direct, comm);

  std::vector<unsigned char> touches;
  build_rows(w.sorted, static_cast<int>(n), s.first_row, s, touches);
  mark_floating(comm, static_cast<int>(n), s.first_row, touches, s);
}

}  // namespace ohmdem
