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

// `skip` leaves one pass out (jackknife); skip >= n leaves none out.
ZoneFit zone_fit(const ZoneTable &t, const std::vector<double> &r, std::size_t skip)
{
  ZoneFit best;
  double best_gain = -1;
  for (int f = 0; f < ZoneTable::kPhi; ++f)
    for (int q = 0; q < ZoneTable::kP; ++q) {
      double rg = 0, gg = 0;
      for (std::size_t j = 0; j < t.n; ++j) {
        if (j == skip) continue;
        const double g = t.at(j, f, q);
        rg += r[j] * g;
        gg += g * g;
      }
      if (gg <= 0) continue;
      const double gain = rg * rg / gg;  // RSS = sum r^2 - gain
      if (gain > best_gain) {
        best_gain = gain;
        best.c = rg / gg;
        best.phi_deg = f;
      }
    }
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
      const double u = (t[j] - t0) * rate;
      const auto i = std::min(static_cast<std::size_t>(std::max(u, 0.0)), shaft_angle->size() - 1);
      a[j] = (*shaft_angle)[i];
    } else {
      a[j] = 2 * kPi * fr * t[j];
    }
  }
  return a;
}

}  // namespace ohmdem::post
