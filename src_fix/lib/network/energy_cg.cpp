// SPDX-License-Identifier: GPL-2.0-or-later
// CG that stops on the error of the power; see energy_cg.h.
#include "network/energy_cg.h"

#include <_hypre_parcsr_mv.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace ohmdem {

namespace {

using Pair = std::pair<const double *, const double *>;

// Local dot products of n entries, then each summed over the ranks in rank order; `extra`:
// further local values summed the same way, in the same exchange.
template <std::size_t N, std::size_t E = 0>
std::array<double, N + E> ordered_dots(MPI_Comm comm, int n, const std::array<Pair, N> &xy,
                                       const std::array<double, E> &extra = {})
{
  std::array<double, N + E> mine{};
  for (std::size_t k = 0; k < N; ++k) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += xy[k].first[i] * xy[k].second[i];
    mine[k] = sum;
  }
  for (std::size_t k = 0; k < E; ++k) mine[N + k] = extra[k];
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<double> all((N + E) * static_cast<std::size_t>(size));
  MPI_Allgather(mine.data(), N + E, MPI_DOUBLE, all.data(), N + E, MPI_DOUBLE, comm);
  std::array<double, N + E> out{};
  for (int r = 0; r < size; ++r)
    for (std::size_t k = 0; k < N + E; ++k) out[k] += all[r * (N + E) + k];
  return out;
}

}  // namespace

double *local_data(HYPRE_ParVector v)
{
  return hypre_VectorData(hypre_ParVectorLocalVector(reinterpret_cast<hypre_ParVector *>(v)));
}

EnergyCgResult energy_cg(MPI_Comm comm, HYPRE_ParCSRMatrix A, HYPRE_Solver amg,
                         const EnergyCgVectors &v, int n, double rhs_sum, const EnergyCgOptions &o)
{
  double *const xd = local_data(v.x), *const bd = local_data(v.b), *const rd = local_data(v.r),
               *const zd = local_data(v.z), *const pd = local_data(v.p), *const qd = local_data(v.q);
  EnergyCgResult out;
  // r = b - A x
  std::copy(bd, bd + n, rd);
  HYPRE_ParCSRMatrixMatvec(-1.0, A, v.x, 1.0, v.r);
  const auto start = ordered_dots<3, 1>(comm, n, {{{bd, bd}, {bd, xd}, {xd, rd}}}, {{rhs_sum}});
  const double norm_b = std::sqrt(start[0]);
  double energy = start[3] - start[1] - start[2];  // P(x0) = c - b'x0 - x0'r0
  if (!(norm_b > 0.0)) return out;
  auto precondition = [&] {
    std::fill(zd, zd + n, 0.0);
    HYPRE_BoomerAMGSolve(amg, A, v.r, v.z);
  };
  precondition();
  std::copy(zd, zd + n, pd);
  const auto first = ordered_dots<2>(comm, n, {{{rd, rd}, {rd, zd}}});
  double rr = first[0], rz = first[1];
  out.converged = std::sqrt(rr) <= o.tolerance * norm_b;
  // The decreases of the last kDelay steps: their slowest ratio is the rate of the tail (a
  // plateau, as CG goes through with conductances over many decades, has ratios near 1 and
  // so never stops it).
  constexpr int kDelay = 3;
  std::array<double, kDelay> recent{};
  while (!out.converged && out.iterations < o.max_iterations) {
    HYPRE_ParCSRMatrixMatvec(1.0, A, v.p, 0.0, v.q);
    const double pAp = ordered_dots<1>(comm, n, {{{pd, qd}}})[0];
    if (!(pAp > 0.0) || !(rz > 0.0)) break;  // lost to rounding: report the residual
    const double alpha = rz / pAp;
    for (int i = 0; i < n; ++i) {
      xd[i] += alpha * pd[i];
      rd[i] -= alpha * qd[i];
    }
    ++out.iterations;
    const double decrease = alpha * rz;
    energy -= decrease;
    recent[out.iterations % kDelay] = decrease;
    precondition();
    const auto d = ordered_dots<2>(comm, n, {{{rd, rd}, {rd, zd}}});
    rr = d[0];
    // The error left: the decreases to come, a geometric tail at the slowest recent rate.
    double rate = 0.0;
    for (int j = 1; j < kDelay; ++j) {
      const double now = recent[(out.iterations - j + 1) % kDelay];
      const double before = recent[(out.iterations - j) % kDelay];
      rate = std::max(rate, before > 0.0 ? now / before : 1.0);
    }
    const double left = rate < 1.0 ? decrease * rate / (1.0 - rate) : HUGE_VAL;
    out.converged = (out.iterations >= kDelay && left <= o.energy_tolerance * energy) ||
                    std::sqrt(rr) <= o.tolerance * norm_b;
    const double beta = d[1] / rz;
    rz = d[1];
    for (int i = 0; i < n; ++i) pd[i] = zd[i] + beta * pd[i];
  }
  out.relative_residual = std::sqrt(rr) / norm_b;
  return out;
}

}  // namespace ohmdem
