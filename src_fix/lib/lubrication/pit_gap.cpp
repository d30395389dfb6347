// SPDX-License-Identifier: GPL-2.0-or-later
// A pit as a strip under a lubricated contact; see pit_gap.h.
#include "lubrication/pit_gap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/constants.h"

namespace ohmdem::lubrication {

namespace {

// Gauss-Legendre, 8 points on [-1, 1] (Abramowitz and Stegun 25.4.30): the positive nodes.
constexpr double kNode[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                             0.9602898564975363};
constexpr double kWeight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                               0.1012285362903763};
// Bisection depth at most: a panel of 2^-40 of its piece is far below any scale of the gap.
constexpr int kMaxDepth = 40;

template <std::size_t N>
using Vec = std::array<double, N>;

template <std::size_t N, class F>
Vec<N> gauss8(const F &f, double t0, double t1)
{
  const double half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
  Vec<N> s{};
  for (int i = 0; i < 4; ++i) {
    const Vec<N> lo = f(mid - half * kNode[i]), hi = f(mid + half * kNode[i]);
    for (std::size_t k = 0; k < N; ++k) s[k] += kWeight[i] * (lo[k] + hi[k]);
  }
  for (double &v : s) v *= half;
  return s;
}

// Adaptive Gauss-Legendre: a panel is split until its two halves agree with it to tol (the
// tolerance halves with the panel) or to 1e-13 of their sum (a narrow panel that holds much of
// the integral would otherwise chase its rounding), at most kMaxDepth deep and kMaxPanels
// panels per call (`budget`: a last guard against an integrand whose noise exceeds both).
// Deterministic: the same inputs give the same panels.
constexpr int kMaxPanels = 1000;
template <std::size_t N, class F>
Vec<N> adapt(const F &f, double t0, double t1, const Vec<N> &whole, Vec<N> tol, int depth,
             int &budget)
{
  const double tm = 0.5 * (t0 + t1);
  const Vec<N> l = gauss8<N>(f, t0, tm), r = gauss8<N>(f, tm, t1);
  bool done = depth >= kMaxDepth || --budget <= 0;
  Vec<N> sum{};
  for (std::size_t k = 0; k < N; ++k) sum[k] = l[k] + r[k];
  if (!done) {
    done = true;
    for (std::size_t k = 0; k < N; ++k)  // tol, or the rounding of the panel's own sum
      done = done && std::fabs(sum[k] - whole[k]) <= std::max(tol[k], 1e-13 * std::fabs(sum[k]));
  }
  if (done) return sum;
  for (double &v : tol) v *= 0.5;
  const Vec<N> a = adapt<N>(f, t0, tm, l, tol, depth + 1, budget);
  const Vec<N> b = adapt<N>(f, tm, t1, r, tol, depth + 1, budget);
  for (std::size_t k = 0; k < N; ++k) sum[k] = a[k] + b[k];
  return sum;
}
template <std::size_t N, class F>
Vec<N> integrate(const F &f, double t0, double t1, const Vec<N> &tol, int &budget)
{
  return adapt<N>(f, t0, t1, gauss8<N>(f, t0, t1), tol, 0, budget);
}

// The pieces' ends: lo, hi and, inside them, the points where the profile is not smooth and
// the extra points given (at most 4), sorted and distinct. No allocation.
struct Breaks {
  std::array<double, 9> x{};
  int n = 0;
};
Breaks breaks(const PitStrip &p, double lo, double hi, const double *extra, int n_extra)
{
  Breaks out;
  const auto add = [&](double v) {
    if (v >= lo && v <= hi) out.x[out.n++] = v;
  };
  add(lo);
  add(hi);
  add(0.5 * (p.x1 + p.x2));  // the centre: the cusp where the two edges' sags meet
  if (p.edge_radius > 0.0 && p.depth < p.edge_radius) {
    // Where the sag reaches the floor: R - sqrt(R^2 - d^2) = depth.
    const double d = std::sqrt(p.depth * (2.0 * p.edge_radius - p.depth));
    add(p.x1 + d);
    add(p.x2 - d);
  }
  for (int i = 0; i < n_extra; ++i) add(extra[i]);
  std::sort(out.x.begin(), out.x.begin() + out.n);
  out.n = static_cast<int>(std::unique(out.x.begin(), out.x.begin() + out.n) - out.x.begin());
  return out;
}

// asin clamped to its domain (the pieces' ends are within [-c, c] up to rounding).
double asin_clamped(double v)
{
  return std::asin(std::clamp(v, -1.0, 1.0));
}

}  // namespace

void check_strip(const PitStrip &p)
{
  if (!(p.x1 < p.x2) || !std::isfinite(p.x1) || !std::isfinite(p.x2))
    throw std::invalid_argument("pit strip: the edges must be finite with x1 < x2, got " +
                                std::to_string(p.x1) + " and " + std::to_string(p.x2));
  if (!(p.depth >= 0.0) || !std::isfinite(p.depth))
    throw std::invalid_argument("pit strip: the depth must be finite and >= 0, got " +
                                std::to_string(p.depth));
  if (!(p.edge_radius >= 0.0) || !std::isfinite(p.edge_radius))
    throw std::invalid_argument("pit strip: the edge radius must be finite and >= 0, got " +
                                std::to_string(p.edge_radius));
}

double strip_recess(const PitStrip &p, double x)
{
  if (!(x > p.x1 && x < p.x2)) return 0.0;
  if (!(p.edge_radius > 0.0)) return p.depth;
  const double d = std::min(x - p.x1, p.x2 - x), r = p.edge_radius;
  // pit_recess's r - sqrt(r^2 - d^2), written without its cancellation near the edges (there
  // it is d^2/2r ~ 1e-10 m, and a rounding of r's ulp, 1e-18 m, would be noise to erfc).
  const double on_edge = d < r ? d * d / (r + std::sqrt((r - d) * (r + d))) : r;
  return std::min(p.depth, on_edge);
}

double strip_gap_capacitance(const GapGeometry &g, double eps_r, const PitStrip &p)
{
  check_strip(p);
  const double base = gap_capacitance(g, eps_r);
  const double rw = g.r_wet, lo = std::max(p.x1, -rw), hi = std::min(p.x2, rw);
  if (!(lo < hi) || !(p.depth > 0.0)) return base;
  const bool ellipse = g.a > 0.0 && g.b > 0.0;
  // The ellipse's span along x, and where it crosses the circle (only when it reaches past it).
  double xi = -1.0;
  if (ellipse && g.a != g.b) {
    const double x2 = (rw * rw - g.a * g.a) / (1.0 - g.a * g.a / (g.b * g.b));
    if (x2 > 0.0 && x2 < std::min(g.b * g.b, rw * rw)) xi = std::sqrt(x2);
  }
  double extra[4];
  int n_extra = 0;
  if (ellipse) extra[n_extra++] = -g.b, extra[n_extra++] = g.b;
  if (xi > 0.0) extra[n_extra++] = -xi, extra[n_extra++] = xi;
  const Breaks x = breaks(p, lo, hi, extra, n_extra);
  const double two_ry = 2.0 * g.ry, inv_2rx = 0.5 / g.rx;
  // F(A) of pit_gap.h: 2 sqrt(2 ry / A) [atan(Yc / s) - atan(Ye / s)], s = sqrt(2 ry A), the
  // difference as one arctangent (both arguments >= 0): atan(s (Yc - Ye) / (s^2 + Yc Ye)).
  const auto chord = [&](double a_gap, double yc, double ye) {
    const double s2 = two_ry * a_gap, s = std::sqrt(s2);
    return 2.0 * two_ry / s * std::atan(s * (yc - ye) / (s2 + yc * ye));
  };
  const auto change = [&](double xx) {
    const double r = strip_recess(p, xx);
    const double yc = std::sqrt(std::max(rw * rw - xx * xx, 0.0));
    const double ye =
        ellipse && std::fabs(xx) < g.b ? g.a * std::sqrt(1.0 - xx * xx / (g.b * g.b)) : 0.0;
    if (!(r > 0.0) || !(yc > ye)) return 0.0;
    const double a0 = g.h0 + xx * xx * inv_2rx;
    return chord(a0 + r, yc, ye) - chord(a0, yc, ye);
  };
  const double scale = kEpsilon0 * eps_r;
  // Tolerance: 1e-11 of the whole gap's capacitance, shared over the pieces by their length.
  const double tol = 1e-11 * base / scale / (hi - lo);
  double sum = 0.0;
  int budget = kMaxPanels;
  for (int k = 0; k + 1 < x.n; ++k) {
    const double u = x.x[k], v = x.x[k + 1];
    // x = c sin t: c = b on the ellipse's span (its chord's square root at +-b), else r_wet.
    const double c = ellipse && g.b < rw && u >= -g.b && v <= g.b ? g.b : rw;
    const auto f = [&](double t) { return Vec<1>{c * std::cos(t) * change(c * std::sin(t))}; };
    const double t0 = asin_clamped(u / c), t1 = asin_clamped(v / c);
    sum += integrate<1>(f, t0, t1, {tol * (v - u)}, budget)[0];
  }
  return base + scale * sum;
}

HertzOverPit hertz_over_pit(const HertzFilm &film, const PitStrip &p)
{
  check_strip(p);
  HertzOverPit out;
  const double a = film.a, b = film.b, area = kPi * a * b;
  const double k = 1.0 / (film.sigma * std::sqrt(2.0));
  const double f0 = std::erfc(film.h_min * k);
  const double lo = std::max(p.x1, -b), hi = std::min(p.x2, b);
  // The part of the ellipse outside the strip keeps the film's gap.
  const auto outside = [&](double rest) {
    out.metallic += f0 * rest;
    if (film.h_c > 0.0) out.free_h += (1.0 - f0) * rest / film.h_c;
  };
  if (!(area > 0.0) || !(lo < hi) || !(p.depth > 0.0)) {
    outside(area);
    out.metallic = area > 0.0 ? out.metallic / area : f0;
    return out;
  }
  if (p.x1 < -b && p.x2 > b) out.min_recess = std::min(strip_recess(p, -b), strip_recess(p, b));
  // x = b sin t: the chord 2 a cos t, dx = b cos t dt; the ellipse's area over [t0, t1] is
  // a b [t + sin t cos t].
  const auto f = [&](double t) {
    const double cs = std::cos(t), w = 2.0 * a * b * cs * cs;
    const double r = strip_recess(p, b * std::sin(t));
    // 1 - f as erf where f is near 1 (a film of almost nothing at the strip's rounded edges):
    // 1 - erfc(z) would leave only rounding there, divided by the tiny h.
    const double z = (film.h_min + r) * k, h = film.h_c + r;
    const double fm = std::erfc(z), free = z < 0.5 ? std::erf(z) : 1.0 - fm;
    return Vec<2>{w * fm, h > 0.0 ? w * free / h : 0.0};
  };
  const Breaks x = breaks(p, lo, hi, nullptr, 0);
  const double ta = asin_clamped(lo / b), tb = asin_clamped(hi / b);
  const double over =
      a * b * ((tb + std::sin(tb) * std::cos(tb)) - (ta + std::sin(ta) * std::cos(ta)));
  outside(area - over);
  // The scale of (1 - f)/h for the tolerance: at most ~1/h_c, and ~1/sigma where h_c -> 0
  // (1 - f = erf((h_min + r)/(sigma sqrt 2)) ~ r/sigma as h = h_c + r -> 0).
  const double h_ref = std::max(film.h_c, film.sigma);
  Vec<2> sum{};
  int budget = kMaxPanels;
  for (int i = 0; i + 1 < x.n; ++i) {
    const double t0 = asin_clamped(x.x[i] / b), t1 = asin_clamped(x.x[i + 1] / b);
    const double share = 1e-12 * (t1 - t0) / kPi;
    const Vec<2> s = integrate<2>(f, t0, t1, {share * area, share * area / h_ref}, budget);
    sum[0] += s[0];
    sum[1] += s[1];
  }
  out.metallic = (out.metallic + sum[0]) / area;
  out.free_h += sum[1];
  return out;
}

}  // namespace ohmdem::lubrication
