// SPDX-License-Identifier: GPL-2.0-or-later
// Contacts as points for ParaView, next to the network (network_export.h) and the particles
// (scene_vtk.h): one vertex cell per contact at its contact point, with the contact's values
// as point data (the lubricated bearing's films and currents). Plain C++ (no LIGGGHTS types).
#ifndef OHMDEM_CONTACT_POINTS_VTK_H
#define OHMDEM_CONTACT_POINTS_VTK_H

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace ohmdem {

struct ContactPoint {
  std::int64_t ball = 0;       // the particle's tag
  int race = 0;                // which race: 0 the high electrode's, 1 the low one's
  double at[3] = {0, 0, 0};    // the contact point (m)
  std::vector<double> values;  // one per name, in the names' order
};

// ASCII legacy VTK, DATASET POLYDATA: POINTS, one VERTICES cell per point, POINT_DATA `ball`,
// `race` and one SCALARS per name. Points are written in the order given (the caller sorts).
// Throws std::invalid_argument if a point has the wrong number of values or a name is not a
// single word.
void write_contact_points_vtk(std::ostream &os, const std::vector<ContactPoint> &points,
                              const std::vector<std::string> &names, const std::string &title);

}  // namespace ohmdem

#endif
