// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/load_zone_fit.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace ohmdem::post {

namespace {

struct ZoneFit {
  double c = 0, phi_deg = 0;
};
struct ZoneTable {
  std::vector<double> g;  // [pass][phi][p]
  std::size_t n = 0;
  static constexpr int kPhi = 360, kP = 7;
  double at(std::size_t j, int f, int q) const { return g[(j * kPhi + f) * kP + q]; }
};

ZoneTable zone_table(const std::vector<double> &theta)
{
  ZoneTable t;
  t.n = theta.size();
  t.g.resize(t.n * ZoneTable::kPhi * ZoneTable::kP);
  for (std::size_t j = 0; j < t.n; ++j)
    for (int f = 0; f < ZoneTable::kPhi; ++f) {
      const double c = std::cos(theta[j] - f * kPi / 180);
      for (int q = 0; q < ZoneTable::kP; ++q)
        t.g[(j * ZoneTable::kPhi + f) * ZoneTable::kP + q] = c > 0 ? std::pow(c, 1 + 0.5 * q) : 0;
    }
  return t;
}

// The least-squares gain (sum r^2 - RSS) of phi = f deg, p = 1 + q / 2, and its c.
double zone_gain(const ZoneTable &t, const std::vector<double> &r, std::size_t skip, int f, int q,
                 double &c)
{
  double rg = 0, gg = 0;
  for (std::size_t j = 0; j < t.n; ++j) {
    if (j == skip) continue;
    const double g = t.at(j, f, q);
    rg += r[j] * g;
    gg += g * g;
  }
  if (gg <= 0) return -1;
  c = rg / gg;
  return rg * rg / gg;
}

// `skip` leaves one pass out (jackknife); skip >= n leaves none out. The best grid point, then
// phi at the vertex of the parabola through the gains at it and its two neighbours (same p): a
// place between the grid's degrees, so that the jackknife's spread does not collapse to the
// grid's steps (an argmax on a grid moves by whole steps or not at all).
ZoneFit zone_fit(const ZoneTable &t, const std::vector<double> &r, std::size_t skip)
{
  ZoneFit best;
  double best_gain = -1;
  int best_q = 0;
  for (int f = 0; f < ZoneTable::kPhi; ++f)
    for (int q = 0; q < ZoneTable::kP; ++q) {
      double c = 0;
      const double gain = zone_gain(t, r, skip, f, q, c);
      if (gain > best_gain) {
        best_gain = gain;
        best.c = c;
        best.phi_deg = f;
        best_q = q;
      }
    }
  if (best_gain <= 0) return best;
  const int f = static_cast<int>(best.phi_deg);
  double c = 0;
  const double below =
      zone_gain(t, r, skip, (f + ZoneTable::kPhi - 1) % ZoneTable::kPhi, best_q, c);
  const double above = zone_gain(t, r, skip, (f + 1) % ZoneTable::kPhi, best_q, c);
  const double curvature = below - 2 * best_gain + above;
  if (below >= 0 && above >= 0 && curvature < 0)
    best.phi_deg = wrap_deg(f + std::clamp(0.5 * (below - above) / curvature, -0.5, 0.5));
  return best;
}

}  // namespace

double wrap_deg(double a)
{
  return a - 360 * std::floor(a / 360);
}

ZoneEstimate zone_estimate(const std::vector<double> &theta, const std::vector<double> &r)
{
  const std::size_t n = r.size();
  const ZoneTable t = zone_table(theta);
  const ZoneFit all = zone_fit(t, r, n);
  double sc = 0, sc2 = 0, sp = 0, sp2 = 0;
  for (std::size_t j = 0; j < n; ++j) {  // jackknife over the passes
    const ZoneFit k = zone_fit(t, r, j);
    const double dphi = wrap_deg(k.phi_deg - all.phi_deg + 180) - 180;
    sc += k.c;
    sc2 += k.c * k.c;
    sp += dphi;
    sp2 += dphi * dphi;
  }
  const double nn = static_cast<double>(n);
  ZoneEstimate e;
  e.c = all.c;
  e.phi_deg = all.phi_deg;
  e.c_se = std::sqrt((nn - 1) / nn * std::max(sc2 - sc * sc / nn, 0.0));
  e.phi_sd = std::sqrt((nn - 1) / nn * std::max(sp2 - sp * sp / nn, 0.0));
  return e;
}

std::vector<double> shaft_angles_at(const std::vector<double> &t, double rate, double t0,
                                    const std::vector<double> *shaft_angle, double fr)
{
  std::vector<double> a(t.size());
  for (std::size_t j = 0; j < a.size(); ++j) {
    if (shaft_angle && !shaft_angle->empty()) {
      // between the samples around t, the angle being accumulated (the sample at or before t
      // would read it half a sample early on average: 1.4 deg of shaft at 500 rad/s, 10 kHz)
      const std::vector<double> &th = *shaft_angle;
      const double u = std::clamp((t[j] - t0) * rate, 0.0, static_cast<double>(th.size() - 1));
      const auto i = std::min(static_cast<std::size_t>(u), th.size() - 1);
      const double frac = u - static_cast<double>(i);
      a[j] = frac > 0 ? th[i] + frac * (th[i + 1] - th[i]) : th[i];
    } else {
      a[j] = 2 * kPi * fr * t[j];
    }
  }
  return a;
}

}  // namespace ohmdem::post
