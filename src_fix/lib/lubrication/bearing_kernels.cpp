// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricated bearing's two kernels; see bearing_kernels.h.
#include "lubrication/bearing_kernels.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ohmdem::lubrication {

namespace {

typedef double v2d __attribute__((vector_size(16)));
typedef std::int64_t v2i __attribute__((vector_size(16)));
constexpr std::int64_t kAbsMask = 0x7fffffffffffffff;

// A race's smallest film.minimum and lambda over its records, as RaceAdmittance::contacts()
// folds them: a NaN is passed over, as std::min(smallest, x) passes it, and the smallest
// lambda is the smallest film's times 1/sigma (rounding is monotonic).
RaceAdmittance::Minima plain_race(const RaceAdmittance &r, const ContactBatch &in,
                                  ContactAdmittance *out)
{
  RaceAdmittance::Minima m;
  for (std::size_t k = 0; k < in.size(); ++k) {
    r.contact(in.fn()[k], in.speed()[k], in.g_dry()[k], in.recess()[k], out[k]);
    m.minimum = std::min(m.minimum, out[k].film.minimum);
    m.lambda = std::min(m.lambda, out[k].lambda);
  }
  return m;
}

}  // namespace

double entrainment_speed(const BallMotion &ball, int side, const RaceFrame &m)
{
  const double *x = ball.x, *v = ball.v;
  const double px = ball.px[side], py = ball.py[side];
  const double ox = x[0] - m.cx, oy = x[1] - m.cy;
  const double orbit = (ox * v[1] - oy * v[0]) / (ox * ox + oy * oy);
  const double nx = px - x[0], ny = py - x[1];
  const double d = nx * (px - m.cx) + ny * (py - m.cy), n2 = nx * nx + ny * ny;
  const double along =
      0.5 * (nx * (v[1] + m.vcy) - ny * (v[0] + m.vcx) + ball.omega_z * n2 + m.w * d) - orbit * d;
  return std::fabs(along) / std::sqrt(n2);
}

RaceMinima PlainKernel::contacts(const RaceAdmittance &a, const ContactBatch &in_a,
                                 ContactAdmittance *out_a, const RaceAdmittance &b,
                                 const ContactBatch &in_b, ContactAdmittance *out_b)
{
  return {plain_race(a, in_a, out_a), plain_race(b, in_b, out_b)};
}

// entrainment_speed() of both sides, lane s side s's: each lane the scalar form's operations in
// its order (SSE2, two doubles per operation), so the same bits.
std::array<double, 2> LanesKernel::speeds(const BallMotion &ball, const RaceFrame race[2])
{
  const double *x = ball.x, *v = ball.v;
  const v2d cx = {race[0].cx, race[1].cx}, cy = {race[0].cy, race[1].cy};
  const v2d w = {race[0].w, race[1].w};
  const v2d vcx = {race[0].vcx, race[1].vcx}, vcy = {race[0].vcy, race[1].vcy};
  const v2d px = {ball.px[0], ball.px[1]}, py = {ball.py[0], ball.py[1]};
  const v2d ox = x[0] - cx, oy = x[1] - cy;
  const v2d orbit = (ox * v[1] - oy * v[0]) / (ox * ox + oy * oy);
  const v2d nx = px - x[0], ny = py - x[1];
  const v2d d = nx * (px - cx) + ny * (py - cy), n2 = nx * nx + ny * ny;
  const v2d along =
      0.5 * (nx * (v[1] + vcy) - ny * (v[0] + vcx) + ball.omega_z * n2 + w * d) - orbit * d;
  const v2d norm = (v2d)_mm_sqrt_pd((__m128d)n2);  // correctly rounded, as std::sqrt
  const v2d magnitude = (v2d)((v2i)along & v2i{kAbsMask, kAbsMask});  // fabs
  const v2d speed = magnitude / norm;
  return {speed[0], speed[1]};
}

// series() with y = {G, B} two doubles per operation: each lane the scalar form's operations,
// so the same bits. x - y is x + (-y) and (-x) y is -(x y) exactly, so its
// (pr sr - pi (-si), pr (-si) + pi sr) is (pr sr + pi si, pi sr + (-(pr si))).
std::complex<double> LanesKernel::series(std::complex<double> a, std::complex<double> b)
{
  const v2d y1 = {a.real(), a.imag()}, y2 = {b.real(), b.imag()};
  const v2d s = y1 + y2;  // sr, si
  if (_mm_movemask_pd(_mm_cmpeq_pd((__m128d)s, _mm_setzero_pd())) == 3) return 0.0;
  const v2d neg_lo = (v2d)v2i{std::int64_t(0x8000000000000000ull), 0};  // -x in lane 0
  // pr = r1 r2 - i1 i2, pi = r1 i2 + i1 r2
  const v2d p =
      v2d{y1[0], y1[0]} * y2 + (v2d)((v2i)(v2d{y1[1], y1[1]} * v2d{y2[1], y2[0]}) ^ (v2i)neg_lo);
  const v2d sq = s * s;
  const double n = sq[0] + sq[1];
  const v2d q = v2d{p[1], p[0]} * (v2d)((v2i)v2d{s[1], s[1]} ^ (v2i)(v2d{0.0, -0.0}));
  const v2d y = (p * v2d{s[0], s[0]} + q) / v2d{n, n};
  return {y[0], y[1]};
}

bool bearing_kernel_named(const std::string &name, BearingKernel &kernel)
{
  if (name == PlainKernel::kName) {
    kernel = BearingKernel::plain;
    return true;
  }
  if (name == LanesKernel::kName) {
    kernel = BearingKernel::lanes;
    return true;
  }
  return false;
}

const char *bearing_kernel_name(BearingKernel kernel)
{
  return kernel == BearingKernel::plain ? PlainKernel::kName : LanesKernel::kName;
}

}  // namespace ohmdem::lubrication
