// SPDX-License-Identifier: GPL-2.0-or-later
// Contacts as VTK points; see contact_points_vtk.h.
#include "writers/contact_points_vtk.h"

#include <ostream>
#include <stdexcept>

#include "writers/scene_vtk.h"

namespace ohmdem {

void write_contact_points_vtk(std::ostream &os, const std::vector<ContactPoint> &points,
                              const std::vector<std::string> &names, const std::string &title)
{
  for (const std::string &name : names)
    if (name.empty() || name.find_first_of(" \t\n") != std::string::npos)
      throw std::invalid_argument("contact point VTK: a data name must be one word, got '" + name +
                                  "'");
  for (const ContactPoint &p : points)
    if (p.values.size() != names.size())
      throw std::invalid_argument("contact point VTK: ball " + std::to_string(p.ball) + " has " +
                                  std::to_string(p.values.size()) + " values for " +
                                  std::to_string(names.size()) + " names");
  const std::size_t n = points.size();
  write_vertex_points(os, title, n, [&](std::size_t k) { return points[k].at; });
  os << "POINT_DATA " << n << "\nSCALARS ball double 1\nLOOKUP_TABLE default\n";
  for (const ContactPoint &p : points) os << static_cast<double>(p.ball) << '\n';
  os << "SCALARS race double 1\nLOOKUP_TABLE default\n";
  for (const ContactPoint &p : points) os << p.race << '\n';
  for (std::size_t k = 0; k < names.size(); ++k) {
    os << "SCALARS " << names[k] << " double 1\nLOOKUP_TABLE default\n";
    for (const ContactPoint &p : points) os << p.values[k] << '\n';
  }
}

}  // namespace ohmdem
