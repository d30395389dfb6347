// SPDX-License-Identifier: GPL-2.0-or-later
// The conduction laws: paper eq. 1 with the small-angle bound, Holm's constriction; see
// conductance_laws.h, doc/methods/conduction_network.md and doc/compute_network_resistance.md.
#include "conduction/conductance_laws.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ohmdem {

double sphere_volume(double radius)
{
  return 4.0 / 3.0 * kPi * radius * radius * radius;
}

double spot_radius(double area)
{
  return area > 0.0 ? std::sqrt(area / kPi) : 0.0;
}

double angle_between(const double u[3], const double v[3])
{
  const double cx = u[1] * v[2] - u[2] * v[1];
  const double cy = u[2] * v[0] - u[0] * v[2];
  const double cz = u[0] * v[1] - u[1] * v[0];
  const double cross = std::sqrt(cx * cx + cy * cy + cz * cz);
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  if (cross == 0.0 && dot == 0.0) return 0.0;  // a zero vector: no direction
  return std::atan2(cross, dot);
}

double min_spot_angle(double area_i, double area_j, double radius)
{
  if (!(radius > 0.0)) return kPi;
  return std::min(kPi, (spot_radius(area_i) + spot_radius(area_j)) / radius);
}

Eq1Result eq1_conductance(double gamma, double area_i, double area_j, double volume, double theta,
                          double radius)
{
  Eq1Result r{0.0, theta, false};
  if (!(gamma > 0.0) || !(area_i > 0.0) || !(area_j > 0.0) || !(volume > 0.0) || !(radius > 0.0) ||
      !std::isfinite(theta))
    return r;
  const double tmin = min_spot_angle(area_i, area_j, radius);
  if (theta < tmin) {
    r.theta = tmin;
    r.clamped = true;
  }
  const double s = std::sin(0.5 * r.theta);
  const double one_minus_cos = 2.0 * s * s;
  r.conductance = gamma * area_i * area_j / (2.0 * volume * one_minus_cos);
  return r;
}

double eq1_conductance_between(double gamma, double area_i, double area_j, double volume,
                               const double u[3], const double v[3], double radius)
{
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const double norms = std::sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) *
                                 (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  // (c_i + c_j)^2 <= 2 (c_i^2 + c_j^2) = 2 (S_i + S_j) / pi < (pi r / 2)^2: clamp angle < 90 deg.
  const bool small_spots = 2.0 * (area_i + area_j) / kPi < 0.25 * kPi * kPi * radius * radius;
  if (dot <= 0.0 && norms > 0.0 && small_spots && gamma > 0.0 && area_i > 0.0 && area_j > 0.0 &&
      volume > 0.0)
    return gamma * area_i * area_j / (2.0 * volume * (1.0 - dot / norms));
  return eq1_conductance(gamma, area_i, area_j, volume, angle_between(u, v), radius).conductance;
}

// Holm, Electric Contacts (4th ed. 1967), sect. 4: both half-spaces, elliptic spot.
double holm_resistance(double rho_e, double a, double b)
{
  if (b > a) std::swap(a, b);
  if (!(a > 0) || !(b > 0)) return std::numeric_limits<double>::infinity();
  return rho_e * complete_elliptic(b / a).K / (kPi * a);
}

double holm_factor(double ellipticity)
{
  return holm_resistance(1.0, 1.0, 1.0 / ellipticity);
}

double series_conductance(double g1, double g2)
{
  if (!(g1 > 0.0) || !(g2 > 0.0)) return 0.0;
  // Not g1 g2 / (g1 + g2): that overflows for large g, and gives NaN for an infinite one.
  return 1.0 / (1.0 / g1 + 1.0 / g2);
}

int for_each_particle_conductance(const ConductingParticle &p, const ContactSpot *spots,
                                  std::size_t n, const EdgeVisitor &visit)
{
  int clamped = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ui[3] = {spots[i].point[0] - p.centre[0], spots[i].point[1] - p.centre[1],
                          spots[i].point[2] - p.centre[2]};
    for (std::size_t j = i + 1; j < n; ++j) {
      if (spots[i].node == spots[j].node) continue;  // same electrode: no current inside
      const double uj[3] = {spots[j].point[0] - p.centre[0], spots[j].point[1] - p.centre[1],
                            spots[j].point[2] - p.centre[2]};
      const Eq1Result r = eq1_conductance(p.gamma, spots[i].area, spots[j].area, p.volume,
                                          angle_between(ui, uj), p.radius);
      clamped += r.clamped;
      if (r.conductance > 0.0) visit(spots[i], spots[j], r.conductance);
    }
  }
  return clamped;
}

int add_particle_conductances(ConductionNetwork &net, const ConductingParticle &p,
                              const ContactSpot *spots, std::size_t n, const EdgeVisitor &on_edge)
{
  return for_each_particle_conductance(
      p, spots, n, [&](const ContactSpot &a, const ContactSpot &b, double g) {
        net.add_conductance(a.node, b.node, g);
        if (on_edge) on_edge(a, b, g);
      });
}

}  // namespace ohmdem
