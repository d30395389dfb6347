// SPDX-License-Identifier: GPL-2.0-or-later
// The bodies around a contact network as legacy-VTK POLYDATA, for ParaView next to the
// network (network_export.h), plain C++ (no LIGGGHTS types): the analytic bearing rings and
// cage as surfaces, the particles as points with their radius (a Glyph of spheres scaled by
// `radius` draws them).
#ifndef OHMDEM_SCENE_VTK_H
#define OHMDEM_SCENE_VTK_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace ohmdem {

// A race: the torus strip of its groove, the groove bottom (where a ball touches) at
// `radius` from the ring centre, the groove's cross-section a circle of radius `groove`.
struct RingShape {
  double centre[2] = {0, 0};  // ring centre in the plane (m)
  double z = 0;               // plane of the balls (m)
  double radius = 0;          // groove bottom (m): Dext/2 or Dinn/2
  double groove = 0;          // groove radius (m)
  bool inner = true;
};
// The cage: a cylindrical band of the pitch radius, height `height`, about its centre.
struct CageShape {
  double centre[2] = {0, 0};
  double z = 0;
  double radius = 0;  // pitch radius (m): Dp/2
  double height = 0;  // m
};

// One file: every ring and the cage (if `cage` is not null) as quadrilateral cells, with
// cell data `body` (0 inner race, 1 outer race, 2 cage) and field data `radius` (m, per body
// in that order: the dimension each is drawn with). `segments` around, `across` over the
// groove arc of +-45 degrees.
void write_bearing_vtk(std::ostream &os, const std::vector<RingShape> &rings, const CageShape *cage,
                       int segments = 120, int across = 8);

// The head of a POLYDATA file of n points, each its own vertex cell: the header with `title`,
// POINTS (17 digits, the stream left at that precision) and VERTICES; at(k) is point k's
// x, y, z. The caller writes the POINT_DATA.
void write_vertex_points(std::ostream &os, const std::string &title, std::size_t n,
                         const std::function<const double *(std::size_t)> &at);

struct ParticlePoint {
  std::int64_t tag;
  double centre[3];
  double radius;
  double potential;  // V
};
// Vertex cells with point data `id`, `radius` (m) and `potential` (V).
void write_particles_vtk(std::ostream &os, const std::vector<ParticlePoint> &particles);

}  // namespace ohmdem

#endif
