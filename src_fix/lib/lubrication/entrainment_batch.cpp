// SPDX-License-Identifier: GPL-2.0-or-later
// EntrainmentBatch: a race's entrainment speeds four per operation (common/lanes4.h), each lane
// entrainment_speed()'s operations in its order (+ - * / sqrt correctly rounded, fabs exact, no
// FMA: built with -ffp-contract=off), so each speed is the scalar function's bits whatever its
// lane or batch. A last group of fewer than four goes through the scalar function. Compiled for
// SSE2 and AVX2, chosen at run time, as race_admittance_batch.cpp.
#include <cstdint>
#include <cstring>

#include "common/lanes4.h"
#include "lubrication/entrainment.h"

namespace ohmdem::lubrication {

namespace {

using lanes::kLanes;
using lanes::v4d;
using lanes::v4u;

OHMDEM_LANES_INLINE v4d load(const double *p)
{
  v4d v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// One contact by the scalar function. Not inlined: the few left after the groups of four would
// otherwise be vectorized by the compiler behind alias checks that cost more than they save.
__attribute__((noinline)) double one(const EntrainmentBatch &in, std::size_t k, const RaceMotion &m)
{
  return entrainment_speed(in.at(k), m);
}

OHMDEM_LANES_INLINE void run(const EntrainmentBatch &in, const RaceMotion &m, double *out)
{
  const std::size_t n = in.size();
  const double *c[EntrainmentBatch::kInputs];
  for (int j = 0; j < EntrainmentBatch::kInputs; ++j) c[j] = in.column(j);
  constexpr std::uint64_t kAbs = 0x7fffffffffffffffull;  // all bits but the sign
  const v4u abs_mask = {kAbs, kAbs, kAbs, kAbs};
  // The ring's motion in locals: stores to out could alias m and force it to be read again.
  const double cx = m.cx, cy = m.cy, w = m.w, vcx = m.vcx, vcy = m.vcy;
  std::size_t i = 0;
  for (; i + kLanes <= n; i += kLanes) {
    const v4d x = load(c[0] + i), y = load(c[1] + i), vx = load(c[2] + i), vy = load(c[3] + i);
    const v4d wz = load(c[4] + i), px = load(c[5] + i), py = load(c[6] + i);
    const v4d rvx = vcx - w * (py - cy), rvy = vcy + w * (px - cx);
    const v4d bvx = vx - wz * (py - y), bvy = vy + wz * (px - x);
    const v4d ox = x - cx, oy = y - cy;
    const v4d orbit = (ox * vy - oy * vx) / (ox * ox + oy * oy);
    const v4d pvx = -orbit * (py - cy), pvy = orbit * (px - cx);
    const v4d nx = px - x, ny = py - y;
    const v4d ux = 0.5 * (bvx + rvx) - pvx, uy = 0.5 * (bvy + rvy) - pvy;
    const v4d t = (v4d)((v4u)(-ny * ux + nx * uy) & abs_mask);  // fabs
    const v4d speed = t / lanes::sqrt(nx * nx + ny * ny);
    std::memcpy(out + i, &speed, sizeof speed);
  }
  for (; i < n; ++i) out[i] = one(in, i, m);
}

__attribute__((target("avx2"))) void speeds_avx2(const EntrainmentBatch &in, const RaceMotion &m,
                                                 double *out)
{
  run(in, m, out);
}

void speeds_sse2(const EntrainmentBatch &in, const RaceMotion &m, double *out)
{
  run(in, m, out);
}

}  // namespace

BallAtContact EntrainmentBatch::at(std::size_t k) const
{
  return {column(0)[k], column(1)[k], column(2)[k], column(3)[k],
          column(4)[k], column(5)[k], column(6)[k]};
}

void EntrainmentBatch::grow()
{
  // The columns move apart: copy each to its new place (n_ values).
  const std::size_t capacity = 2 * capacity_ + 16;
  std::vector<double> data(kInputs * capacity);
  if (n_ > 0)
    for (int j = 0; j < kInputs; ++j)
      std::memcpy(data.data() + j * capacity, column(j), n_ * sizeof(double));
  data_.swap(data);
  capacity_ = capacity;
}

void EntrainmentBatch::speeds(const RaceMotion &m, double *out, bool sse2) const
{
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2 && !sse2)
    speeds_avx2(*this, m, out);
  else
    speeds_sse2(*this, m, out);
}

}  // namespace ohmdem::lubrication
