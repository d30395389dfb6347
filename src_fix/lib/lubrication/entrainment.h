// SPDX-License-Identifier: GPL-2.0-or-later
// The mean entrainment speed of a race's ball contacts, the speed the lubricated film is
// built at (doc/lubricated_contact.md): entrainment_speed() for one contact, and
// EntrainmentBatch for a race's pressed contacts four per operation (entrainment_batch.cpp),
// each the scalar function's bits. Plain C++.
#ifndef OHMDEM_LUBRICATION_ENTRAINMENT_H
#define OHMDEM_LUBRICATION_ENTRAINMENT_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace ohmdem::lubrication {

// A race's rigid motion on this step: centre (m), angular speed (rad/s), centre velocity (m/s).
struct RaceMotion {
  double cx = 0, cy = 0, w = 0, vcx = 0, vcy = 0;
};

// A ball at its contact with a race: centre (m), velocity (m/s), spin about z (rad/s), contact
// point (m).
struct BallAtContact {
  double x = 0, y = 0, vx = 0, vy = 0, wz = 0, px = 0, py = 0;
};

// The tangential component of the mean of the two surfaces' velocities at the contact point,
// relative to the point, which travels with the ball's orbit about the ring centre. Pure rolling
// on a fixed outer ring gives (omega_i - omega_cage) R_i at the inner contact. The ring's
// velocity at the point is FixBearingRace::surface_velocity's, from its rigid motion (m/s).
inline double entrainment_speed(const BallAtContact &b, const RaceMotion &m)
{
  const double rvx = m.vcx - m.w * (b.py - m.cy), rvy = m.vcy + m.w * (b.px - m.cx);
  const double bvx = b.vx - b.wz * (b.py - b.y), bvy = b.vy + b.wz * (b.px - b.x);
  const double ox = b.x - m.cx, oy = b.y - m.cy;
  const double orbit = (ox * b.vy - oy * b.vx) / (ox * ox + oy * oy);
  const double pvx = -orbit * (b.py - m.cy), pvy = orbit * (b.px - m.cx);
  const double nx = b.px - b.x, ny = b.py - b.y;
  const double ux = 0.5 * (bvx + rvx) - pvx, uy = 0.5 * (bvy + rvy) - pvy;
  // The component along the unit tangent (-ny, nx)/|n|: one division.
  return std::fabs(-ny * ux + nx * uy) / std::sqrt(nx * nx + ny * ny);
}

// A race's pressed contacts, one array per input (as ContactBatch): the arrays keep their size
// between steps.
class EntrainmentBatch {
 public:
  static constexpr int kInputs = 7;  // BallAtContact's fields
  std::size_t size() const { return n_; }
  void clear() { n_ = 0; }
  void add(const BallAtContact &b)
  {
    if (n_ == capacity_) grow();
    double *const p = data_.data() + n_;
    p[0 * capacity_] = b.x;
    p[1 * capacity_] = b.y;
    p[2 * capacity_] = b.vx;
    p[3 * capacity_] = b.vy;
    p[4 * capacity_] = b.wz;
    p[5 * capacity_] = b.px;
    p[6 * capacity_] = b.py;
    ++n_;
  }
  // Contact k's inputs.
  BallAtContact at(std::size_t k) const;
  // out[k] = entrainment_speed(at(k), m) bit for bit, k < size(), four per operation: SSE2 or
  // AVX2, the best the CPU has unless `sse2` (the tests compare both).
  void speeds(const RaceMotion &m, double *out, bool sse2 = false) const;
  // Input column j (BallAtContact's field order) of the contacts.
  const double *column(int j) const { return data_.data() + j * capacity_; }

 private:
  void grow();
  std::vector<double> data_;  // kInputs columns of capacity_
  std::size_t n_ = 0, capacity_ = 0;
};

}  // namespace ohmdem::lubrication

#endif
