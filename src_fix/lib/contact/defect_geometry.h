// SPDX-License-Identifier: GPL-2.0-or-later
// Defects as pits: the geometry of a local surface defect of a bearing (plain C++).
//
// A defect is a zone of angular size Δφ on a race (fixed on the ring), or on a ball (turning
// with the ball), or on the cage. Electrically, a contact whose contact point lies in the zone
// carries no current (the paper's contact break). Mechanically the zone is a pit of width w
// (arc length on the surface) and depth h, not a hole with nothing underneath: a ball over it
// drops only as far as the pit lets it, resting on the pit's edges (a sphere of radius r
// touching an edge at horizontal distance d sinks by r - sqrt(r^2 - d^2)) or on its floor
// (h). The approach of the contact is reduced by that recess, so the contact fades out and
// comes back geometrically, without the artificial kilonewton re-entry of a literal mask.
#ifndef OHMDEM_DEFECT_GEOMETRY_H
#define OHMDEM_DEFECT_GEOMETRY_H

namespace ohmdem {

// Angle wrapped to (-pi, pi].
double wrap_angle(double a);

struct Pit {
  double width = 0;        // arc length of the zone on the surface (m)
  double depth = 0;        // floor depth (m), > 0
  double ball_radius = 0;  // radius of the ball that rolls over it (m)
};

// How far the surface under a contact at arc offset s from the pit centre falls away (m):
// 0 outside the pit (|s| >= w/2), min(h, r - sqrt(r^2 - d^2)) inside, d = w/2 - |s| the
// distance to the nearer edge. Continuous, 0 at the edges: re-entry is geometric.
double pit_recess(const Pit &pit, double s);

// Whether the contact at arc offset s lies in the zone (|s| < w/2).
inline bool in_pit(const Pit &pit, double s)
{
  return 2.0 * (s < 0 ? -s : s) < pit.width;
}

// Largest recess of a pit (at its centre): what the ball can drop at most.
double pit_max_recess(const Pit &pit);

}  // namespace ohmdem

#endif
