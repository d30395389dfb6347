// SPDX-License-Identifier: GPL-2.0-or-later
// A pit on a ball of the 3D bearing (plain C++, no LIGGGHTS types): the ball's orientation as a
// unit quaternion, turned each step by its angular velocity, carries the pit's centre (a point
// of the ball's surface) through space; a contact lies in the pit when the angle between the
// contact's direction from the ball centre and the pit's centre is within its half-size.
// doc/methods/bearing_3d.md ("Defects").
#ifndef OHMDEM_BALL_PIT_3D_H
#define OHMDEM_BALL_PIT_3D_H

#include <cmath>

#include "contact/vec3.h"

namespace ohmdem {

// body -> lab rotation of a ball; the identity at the start (the body frame is the lab's).
struct BallOrientation {
  double w = 1, x = 0, y = 0, z = 0;

  // Turn by the angular velocity `omega` (lab frame, rad/s) held for dt: the exact rotation by
  // |omega| dt about omega, applied after the present one; renormalised against round-off.
  void turn(Vec3 omega, double dt)
  {
    const double rate = norm(omega);
    if (!(rate > 0.0)) return;
    const double half = 0.5 * rate * dt, s = std::sin(half) / rate;
    const double qw = std::cos(half), qx = s * omega.x, qy = s * omega.y, qz = s * omega.z;
    const double nw = qw * w - qx * x - qy * y - qz * z;
    const double nx = qw * x + qx * w + qy * z - qz * y;
    const double ny = qw * y - qx * z + qy * w + qz * x;
    const double nz = qw * z + qx * y - qy * x + qz * w;
    const double n = 1.0 / std::sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
    w = nw * n;
    x = nx * n;
    y = ny * n;
    z = nz * n;
  }
  // A body-frame vector in the lab frame.
  Vec3 apply(Vec3 v) const
  {
    const Vec3 u{x, y, z};
    const Vec3 t = 2.0 * cross(u, v);
    return v + w * t + cross(u, t);
  }
};

// The pit's centre in the ball's body frame: at `azimuth` about z from +x and `latitude` above
// the equator (rad), the lab directions at the start.
inline Vec3 ball_pit_centre(double azimuth, double latitude)
{
  return {std::cos(latitude) * std::cos(azimuth), std::cos(latitude) * std::sin(azimuth),
          std::sin(latitude)};
}

// The direction of a race contact from the ball centre: `radial` the unit vector from the axis
// to the ball centre in the bearing plane, alpha the contact angle (torus_race.h's sign): toward
// the axis and -z on an inner race, outward and +z on an outer one.
inline Vec3 contact_direction(Vec3 radial, double alpha, bool inner)
{
  const double c = std::cos(alpha), s = std::sin(alpha), sign = inner ? -1.0 : 1.0;
  return {sign * c * radial.x, sign * c * radial.y, sign * s};
}

// The angle (rad, in [0, pi]) between two unit vectors.
inline double angle_between(Vec3 a, Vec3 b)
{
  return std::atan2(norm(cross(a, b)), dot(a, b));
}

}  // namespace ohmdem

#endif
