// SPDX-License-Identifier: GPL-2.0-or-later
// Contact and bearing admittance; see contact_admittance.h.
#include "lubrication/contact_admittance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/constants.h"
#include "lubrication/gap_forms.h"
#include "lubrication/keyed_cache.h"

namespace ohmdem::lubrication {

using gap_forms::form_mean;
using gap_forms::FormMean;
using gap_forms::kQuarter;

double permittivity_at_pressure(double eps_r, double p)
{
  const double pg = p * 1e-9;
  const double density = 1.0 + 0.6 * pg / (1.0 + 1.7 * pg);
  const double c = (eps_r - 1.0) / (eps_r + 2.0) * density;
  return (1.0 + 2.0 * c) / (1.0 - c);
}

double hertz_mean_permittivity(double eps_r, double p0)
{
  // Gauss-Legendre, 8 points on [-1, 1] (Abramowitz and Stegun 25.4.30), mapped to [0, 1]:
  // nodes t and weights w t of 2 int_0^1 eps(p0 t) t dt.
  static const std::array<std::array<double, 2>, 8> nodes = [] {
    const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                         0.9602898564975363};
    const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                         0.1012285362903763};
    std::array<std::array<double, 2>, 8> n{};
    for (int i = 0; i < 4; ++i) {
      const double t0 = 0.5 * (1.0 - x[i]), t1 = 0.5 * (1.0 + x[i]);
      n[2 * i] = {t0, w[i] * t0};
      n[2 * i + 1] = {t1, w[i] * t1};
    }
    return n;
  }();
  // permittivity_at_pressure as one fraction: with q = p/GPa, rho/rho0 = n/d, n = 1 + 2.3 q,
  // d = 1 + 1.7 q, and c = K n/d, (1 + 2c)/(1 - c) = (d + 2 K n)/(d - K n): one division
  // per node instead of three.
  const double kcm = (eps_r - 1.0) / (eps_r + 2.0), q0 = p0 * 1e-9;
  double s = 0.0;
  for (const auto &[t, wt] : nodes) {
    const double q = q0 * t, d = 1.0 + 1.7 * q, kn = kcm * (1.0 + 2.3 * q);
    s += wt * (d + 2.0 * kn) / (d - kn);
  }
  return s;
}

namespace {

// cos^2 of the midpoints of a quarter turn, once per process.
const std::array<double, kQuarter> &cos2_table()
{
  static const std::array<double, kQuarter> cos2 = [] {
    std::array<double, kQuarter> t{};
    for (int i = 0; i < kQuarter; ++i) {
      const double c = std::cos((i + 0.5) * (0.5 * kPi / kQuarter));
      t[i] = c * c;
    }
    return t;
  }();
  return cos2;
}

// What the gap integral needs of a race: s_out^2 at each angle (the wetted circle in the
// scaled coordinates) and the quadratic form P c^2 + Q s^2 = 2 rx cos^2 + 2 ry sin^2.
struct RaceGap {
  std::array<double, kQuarter> s_out2{};
  double sqrt_p = 0, sqrt_q = 0;
};
const RaceGap &race_gap(double rx, double ry, double r_wet)
{
  thread_local KeyedCache<3, RaceGap> cache;
  return cache.get({rx, ry, r_wet}, [](const std::array<double, 3> &k) {
    const std::array<double, kQuarter> &cos2 = cos2_table();
    RaceGap r;
    for (int i = 0; i < kQuarter; ++i)
      r.s_out2[i] = k[2] * k[2] / (2.0 * k[0] * cos2[i] + 2.0 * k[1] * (1.0 - cos2[i]));
    r.sqrt_p = std::sqrt(2.0 * k[0]);
    r.sqrt_q = std::sqrt(2.0 * k[1]);
    return r;
  });
}
using Boundary = std::array<double, kQuarter>;

// sum over the angles of ln((h0 + s_out^2)/(h0 + s_in^2)), a logarithm per angle.
double log_sum(const GapGeometry &g, const Boundary &s_out2)
{
  const std::array<double, kQuarter> &cos2 = cos2_table();
  double sum = 0.0;
  for (int i = 0; i < kQuarter; ++i) {
    const double c2 = cos2[i], s2 = 1.0 - c2;
    const double s_in2 = g.a > 0.0 && g.b > 0.0
                             ? 1.0 / (2.0 * g.rx * c2 / (g.b * g.b) + 2.0 * g.ry * s2 / (g.a * g.a))
                             : 0.0;
    if (s_out2[i] > s_in2) sum += std::log((g.h0 + s_out2[i]) / (g.h0 + s_in2));
  }
  return sum;
}

}  // namespace

double gap_capacitance(const GapGeometry &g, double eps_r)
{
  const RaceGap &race = race_gap(g.rx, g.ry, g.r_wet);
  const double scale = kEpsilon0 * eps_r * std::sqrt(g.rx * g.ry) * 2.0 * kPi;
  // ln(h0 + s_out^2) = ln(A c^2 + B s^2) - ln(P c^2 + Q s^2) with A = h0 P + r^2,
  // B = h0 Q + r^2; ln(h0 + s_in^2) = ln(A' c^2 + B' s^2) - ln(P' c^2 + Q' s^2) with
  // P' = 2 rx / b^2, Q' = 2 ry / a^2, A' = h0 P' + 1, B' = h0 Q' + 1 (ln h0 with nothing
  // excluded). While the wetted circle holds the ellipse (r_wet > a, b: every angle counts),
  // the midpoint rule of each is form_mean's: two logarithms instead of one per angle.
  const double r2 = g.r_wet * g.r_wet, p = 2.0 * g.rx, q = 2.0 * g.ry;
  const FormMean out = form_mean(std::sqrt(g.h0 * p + r2), std::sqrt(g.h0 * q + r2));
  const FormMean pq = form_mean(race.sqrt_p, race.sqrt_q);
  if (!(g.a > 0.0 && g.b > 0.0)) {
    const double x = out.s / (pq.s * std::sqrt(g.h0)), y = out.y / pq.y;
    return scale *
           (2.0 * std::log(x) + gap_forms::aliasing(y, [](double v) { return std::log(v); }));
  }
  if (g.r_wet > g.a && g.r_wet > g.b) {
    const double sp = std::sqrt(p) / g.b, sq = std::sqrt(q) / g.a;  // sqrt P', sqrt Q'
    const FormMean in = form_mean(std::sqrt(g.h0 * sp * sp + 1.0), std::sqrt(g.h0 * sq * sq + 1.0));
    const FormMean pq_in = form_mean(sp, sq);
    const double x = out.s * pq_in.s / (pq.s * in.s), y = out.y * pq_in.y / (pq.y * in.y);
    return scale *
           (2.0 * std::log(x) + gap_forms::aliasing(y, [](double v) { return std::log(v); }));
  }
  // The ellipse reaches past the wetted circle: angle by angle, as the logarithm of one
  // product (every factor >= 1) without a division: with e = 1/s_in^2,
  // (h0 + s_out^2)/(h0 + s_in^2) = (h0 + s_out^2) e / (h0 e + 1); log_sum if it overflows.
  const Boundary &s_out2 = race.s_out2;
  const std::array<double, kQuarter> &cos2 = cos2_table();
  double num = 1.0, den = 1.0;
  const double ex = p / (g.b * g.b), ey = q / (g.a * g.a);
  for (int i = 0; i < kQuarter; ++i) {
    const double e = ex * cos2[i] + ey * (1.0 - cos2[i]);
    if (s_out2[i] * e > 1.0) {
      num *= (g.h0 + s_out2[i]) * e;
      den *= g.h0 * e + 1.0;
    }
  }
  const double sum =
      num < std::numeric_limits<double>::max() && den < std::numeric_limits<double>::max()
          ? std::log(num / den)
          : log_sum(g, s_out2);
  return scale * sum / kQuarter;
}

double metallic_fraction(double lambda)
{
  return std::erfc(lambda / std::sqrt(2.0));
}

ContactAdmittance contact_admittance(const ContactInput &in)
{
  ContactAdmittance c;
  c.film = hamrock_dowson(in.film);
  c.lambda = film_parameter(c.film.minimum, in.sigma);
  c.gap = c.film.minimum + in.recess;
  c.g_dry = in.g_dry;
  // Over a pit the surfaces are the film plus the recess apart (recess = 0: the film's lambda).
  c.metallic = metallic_fraction(in.recess > 0.0 ? film_parameter(c.gap, in.sigma) : c.lambda);
  const double area = kPi * in.a * in.b;
  const double free = 1.0 - c.metallic;
  const double h = c.film.central + in.recess;
  c.g = c.metallic * in.g_dry;
  if (h > 0.0 && free > 0.0 && area > 0.0) {
    const double p0 = 1.5 * in.film.load / area;  // Hertz peak pressure
    c.c_hertz = free * kEpsilon0 * hertz_mean_permittivity(in.eps_r, p0) * area / h;
    c.g += free * area / (in.resistivity * h);
  }
  GapGeometry gap{
      std::max(c.film.central, in.sigma) + in.recess, in.film.rx, in.film.ry, in.a, in.b, in.r_wet};
  c.c_outer = gap_capacitance(gap, in.eps_r);
  return c;
}

double contact_voltage(std::complex<double> y_self, std::complex<double> y_other, double v)
{
  const std::complex<double> s = y_self + y_other;
  return s == 0.0 ? 0.0 : v * std::abs(y_other / s);
}

bool film_breaks_down(double v, double h, double field)
{
  return field > 0.0 && v > field * h;
}

ContactAdmittance broken_down(const ContactAdmittance &c)
{
  ContactAdmittance b = c;
  b.metallic = 1.0;
  b.c_hertz = 0.0;
  b.g = c.g_dry;
  return b;
}

int break_down_ball(std::complex<double> y[2], const ContactAdmittance c[2], const bool loaded[2],
                    double v, double field, double omega)
{
  bool broken[2] = {false, false};
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < 2; ++s)
      if (loaded[s] && !broken[s] &&
          film_breaks_down(contact_voltage(y[s], y[1 - s], v), c[s].gap, field)) {
        broken[s] = true;
        y[s] = broken_down(c[s]).y(omega);
      }
  return broken[0] + broken[1];
}

double idle_gap_capacitance(double gap, double rx, double ry, double r_wet, double eps_r,
                            double sigma)
{
  return gap_capacitance(GapGeometry{std::max(gap, sigma), rx, ry, 0.0, 0.0, r_wet}, eps_r);
}

Impedance impedance(std::complex<double> y, double omega)
{
  Impedance z;
  const double inf = std::numeric_limits<double>::infinity();
  z.c_parallel = y.imag() / omega;
  z.r_parallel = y.real() > 0.0 ? 1.0 / y.real() : inf;
  if (y == 0.0) {
    z.z_abs = inf;
    return z;
  }
  const std::complex<double> zz = 1.0 / y;
  z.z_abs = std::abs(zz);
  z.z_phase = std::arg(zz);
  return z;
}

}  // namespace ohmdem::lubrication
