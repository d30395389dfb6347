// SPDX-License-Identifier: GPL-2.0-or-later
// The bodies around a contact network as legacy VTK; see scene_vtk.h.
#include "writers/scene_vtk.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>

#include "common/constants.h"

namespace ohmdem {

namespace {

struct Mesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 4>> quads;
  std::vector<int> body;
};

// A surface of revolution about the body's centre: `profile(t)` gives (radial distance,
// height) for t in [0, 1]; closed around, `across` quads over t.
template <class Profile>
void revolve(Mesh &m, const double centre[2], double z, int body, int segments, int across,
             Profile profile)
{
  const int first = static_cast<int>(m.points.size());
  for (int s = 0; s < segments; ++s) {
    const double phi = 2.0 * kPi * s / segments;
    for (int k = 0; k <= across; ++k) {
      double r, h;
      profile(static_cast<double>(k) / across, r, h);
      m.points.push_back({centre[0] + r * std::cos(phi), centre[1] + r * std::sin(phi), z + h});
    }
  }
  const int row = across + 1;
  for (int s = 0; s < segments; ++s) {
    const int a = first + s * row, b = first + ((s + 1) % segments) * row;
    for (int k = 0; k < across; ++k) {
      m.quads.push_back({a + k, b + k, b + k + 1, a + k + 1});
      m.body.push_back(body);
    }
  }
}

}  // namespace

void write_bearing_vtk(std::ostream &os, const std::vector<RingShape> &rings, const CageShape *cage,
                       int segments, int across)
{
  Mesh m;
  std::vector<double> radius(3, 0.0);
  const double arc = kPi / 4.0;  // half the groove arc drawn
  for (const RingShape &r : rings) {
    // The groove's cross-section circle is centred `groove` inside the ring's contact surface:
    // toward the balls, i.e. outward for the inner race and inward for the outer one.
    const double sign = r.inner ? 1.0 : -1.0;
    const double middle = r.radius + sign * r.groove;
    revolve(m, r.centre, r.z, r.inner ? 0 : 1, segments, across,
            [&](double t, double &rad, double &h) {
              const double theta = -arc + 2.0 * arc * t;
              rad = middle - sign * r.groove * std::cos(theta);
              h = r.groove * std::sin(theta);
            });
    radius[r.inner ? 0 : 1] = r.radius;
  }
  if (cage) {
    revolve(m, cage->centre, cage->z, 2, segments, 1, [&](double t, double &rad, double &h) {
      rad = cage->radius;
      h = (t - 0.5) * cage->height;
    });
    radius[2] = cage->radius;
  }
  os << "# vtk DataFile Version 3.0\nohmdem bearing rings and cage\nASCII\nDATASET POLYDATA\n";
  os << std::setprecision(17);
  os << "POINTS " << m.points.size() << " double\n";
  for (const auto &p : m.points) os << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  os << "POLYGONS " << m.quads.size() << ' ' << 5 * m.quads.size() << '\n';
  for (const auto &q : m.quads)
    os << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
  os << "CELL_DATA " << m.quads.size() << "\nSCALARS body int 1\nLOOKUP_TABLE default\n";
  for (int b : m.body) os << b << '\n';
  os << "FIELD FieldData 1\nradius 1 3 double\n"
     << radius[0] << ' ' << radius[1] << ' ' << radius[2] << '\n';
}

void write_vertex_points(std::ostream &os, const std::string &title, std::size_t n,
                         const std::function<const double *(std::size_t)> &at)
{
  os << "# vtk DataFile Version 3.0\n" << title << "\nASCII\nDATASET POLYDATA\n";
  os << std::setprecision(17);
  os << "POINTS " << n << " double\n";
  for (std::size_t k = 0; k < n; ++k) {
    const double *x = at(k);
    os << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
  }
  os << "VERTICES " << n << ' ' << 2 * n << '\n';
  for (std::size_t k = 0; k < n; ++k) os << "1 " << k << '\n';
}

void write_particles_vtk(std::ostream &os, const std::vector<ParticlePoint> &particles)
{
  const std::size_t n = particles.size();
  write_vertex_points(os, "ohmdem particles", n,
                      [&](std::size_t k) { return particles[k].centre; });
  os << "POINT_DATA " << n << "\nSCALARS id double 1\nLOOKUP_TABLE default\n";
  for (const auto &p : particles) os << static_cast<double>(p.tag) << '\n';
  os << "SCALARS radius double 1\nLOOKUP_TABLE default\n";
  for (const auto &p : particles) os << p.radius << '\n';
  os << "SCALARS potential double 1\nLOOKUP_TABLE default\n";
  for (const auto &p : particles) os << p.potential << '\n';
}

}  // namespace ohmdem
