// SPDX-License-Identifier: GPL-2.0-or-later
// Contact and bearing admittance; see contact_admittance.h.
#include "lubrication/contact_admittance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/constants.h"

namespace ohmdem::lubrication {

namespace {
// Midpoints of a quarter turn: the gap integrand is even in x and in y.
constexpr int kQuarter = 32;
}  // namespace

double permittivity_at_pressure(double eps_r, double p)
{
  const double pg = p * 1e-9;
  const double density = 1.0 + 0.6 * pg / (1.0 + 1.7 * pg);
  const double c = (eps_r - 1.0) / (eps_r + 2.0) * density;
  return (1.0 + 2.0 * c) / (1.0 - c);
}

double hertz_mean_permittivity(double eps_r, double p0)
{
  // Gauss-Legendre, 8 points on [-1, 1] (Abramowitz and Stegun 25.4.30), mapped to [0, 1].
  static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                              0.9602898564975363};
  static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                              0.1012285362903763};
  double s = 0.0;
  for (int i = 0; i < 4; ++i)
    for (const double t : {0.5 * (1.0 - x[i]), 0.5 * (1.0 + x[i])})
      s += 0.5 * w[i] * 2.0 * t * permittivity_at_pressure(eps_r, p0 * t);
  return s;
}

double gap_capacitance(const GapGeometry &g, double eps_r)
{
  // cos^2 of the midpoints, once per process (evaluated for every contact at every step).
  static const std::array<double, kQuarter> cos2 = [] {
    std::array<double, kQuarter> t{};
    for (int i = 0; i < kQuarter; ++i) {
      const double c = std::cos((i + 0.5) * (0.5 * kPi / kQuarter));
      t[i] = c * c;
    }
    return t;
  }();
  double sum = 0.0;
  for (int i = 0; i < kQuarter; ++i) {
    const double c2 = cos2[i], s2 = 1.0 - c2;
    const double s_in2 = g.a > 0.0 && g.b > 0.0
                             ? 1.0 / (2.0 * g.rx * c2 / (g.b * g.b) + 2.0 * g.ry * s2 / (g.a * g.a))
                             : 0.0;
    const double s_out2 = g.r_wet * g.r_wet / (2.0 * g.rx * c2 + 2.0 * g.ry * s2);
    if (s_out2 > s_in2) sum += std::log((g.h0 + s_out2) / (g.h0 + s_in2));
  }
  // int_0^{2 pi} = 4 int_0^{pi/2} = 4 (pi/2) / kQuarter * sum
  return kEpsilon0 * eps_r * std::sqrt(g.rx * g.ry) * sum * (2.0 * kPi / kQuarter);
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

std::complex<double> series(std::complex<double> y1, std::complex<double> y2)
{
  const std::complex<double> s = y1 + y2;
  return s == 0.0 ? std::complex<double>(0.0) : y1 * y2 / s;
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
