// SPDX-License-Identifier: GPL-2.0-or-later
// A vector of space (x, y, z), for the 3D bearing's contact kernels (the planar kernels use
// vec2.h). Inline arithmetic only: these run for every ball at every step.
#ifndef OHMDEM_VEC3_H
#define OHMDEM_VEC3_H

#include <cmath>

namespace ohmdem {

struct Vec3 {
  double x = 0;
  double y = 0;
  double z = 0;
};

inline Vec3 operator+(Vec3 a, Vec3 b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator-(Vec3 a)
{
  return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(double s, Vec3 a)
{
  return {s * a.x, s * a.y, s * a.z};
}
inline double dot(Vec3 a, Vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a)
{
  return std::sqrt(dot(a, a));
}

// A rotation as its matrix (rows r[0..2]): lab = R * local, local = R^T * lab.
struct Rot3 {
  Vec3 r[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 apply(Vec3 v) const { return {dot(r[0], v), dot(r[1], v), dot(r[2], v)}; }
  Vec3 apply_transpose(Vec3 v) const { return v.x * r[0] + v.y * r[1] + v.z * r[2]; }
  Vec3 column(int k) const
  {
    return k == 0 ? Vec3{r[0].x, r[1].x, r[2].x}
                  : (k == 1 ? Vec3{r[0].y, r[1].y, r[2].y} : Vec3{r[0].z, r[1].z, r[2].z});
  }
};

// The rotation by |theta| about theta/|theta| (Rodrigues); the identity for theta = 0.
inline Rot3 rotation_vector(Vec3 theta)
{
  const double t = norm(theta);
  Rot3 R;
  if (!(t > 0.0)) return R;
  const Vec3 k = (1.0 / t) * theta;
  const double c = std::cos(t), s = std::sin(t), v = 1.0 - c;
  R.r[0] = {c + k.x * k.x * v, k.x * k.y * v - k.z * s, k.x * k.z * v + k.y * s};
  R.r[1] = {k.y * k.x * v + k.z * s, c + k.y * k.y * v, k.y * k.z * v - k.x * s};
  R.r[2] = {k.z * k.x * v - k.y * s, k.z * k.y * v + k.x * s, c + k.z * k.z * v};
  return R;
}

}  // namespace ohmdem

#endif
