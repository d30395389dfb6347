// SPDX-License-Identifier: GPL-2.0-or-later
// Ball-race contact of the 3D bearing (plain C++, no LIGGGHTS types): a ball free in space, with
// its spin, in the toroidal groove of a rigid ring that may be displaced, tilted and spun
// (torus_race.h gives the geometry and the exact Hertz contact at the contact angle).
// doc/methods/bearing_3d.md.
//
// Normal: Q = K(alpha) delta^1.5 along the contact line, plus the restitution damping of the
// planar kernel (race_contact.h) with S_n = dQ/ddelta; never attractive. Tangential: Coulomb
// friction with a tangential spring kept in the contact's tangent plane (projected onto the
// plane of each step), Mindlin stiffness k_t = 8 G* sqrt(ab), viscous
// damping, |F_t| <= mu F_n. Spin about the contact normal: a torsional spring (Mindlin's
// (16/3) G_t sqrt(ab)^3) capped by the full-sliding spin moment of the Hertz ellipse,
// 3 mu Q a E(e) / 8 (Harris) at the elastic load Q, with restitution damping on the ball's
// moment of inertia.
// Rolling relaxes both springs: the material passes through the contact in the time 2b/V (b the
// ellipse's half-length along the rolling direction, V the surfaces' mean speed past the contact
// point, which travels with the ball's orbit), so a spring holds
// only what the last contact length of travel put into it: ds/dt = v_slip - (V / 2b) s (the
// brush model's first-order relaxation). In steady rolling a tangential force then needs a
// creep, F_t = k_t 2b v_slip / V (a linear creep law), instead of being held by a stuck spring
// while nothing slides; at rest the springs keep their stick.
#ifndef OHMDEM_RACE_CONTACT_3D_H
#define OHMDEM_RACE_CONTACT_3D_H

#include <algorithm>
#include <cmath>

#include "contact/damping.h"
#include "contact/torus_race.h"
#include "contact/vec3.h"

namespace ohmdem {

struct RaceContactModel3d {
  // E_eff, G_eff as the planar kernel; G_torsion = torsion_shear_modulus(...). Throws
  // std::invalid_argument as AngularHertz does and for a friction < 0.
  RaceContactModel3d(const TorusGroove &groove, double E_eff, double G_eff, double G_torsion,
                     double restitution, double friction);
  TorusGroove groove;
  AngularHertz hertz;
  double beta;
  double friction;
};

// The ring at the current step, in the lab frame.
struct RingMotion3d {
  Vec3 centre;          // the ring's centre (m)
  Rot3 tilt;            // lab = tilt * ring frame (the spin about the axis leaves the torus as is)
  Vec3 velocity;        // of the centre (m/s)
  Vec3 omega;           // angular velocity of the ring's material: spin about its axis + tilt rate
  bool tilted = false;  // false: `tilt` is the identity (the ring frame is the lab's), skipped
  double radius_shift = 0;  // u: the ring's radius grows (inner) or shrinks (outer) by u (m)
  double radius_rate = 0;   // du/dt (m/s)
};

struct BallState3d {
  Vec3 x, v, omega;
  double mass = 0, inertia = 0;  // kg, kg m^2
};

// The contact's history between steps: the tangential spring (lab frame, m) and the twist of the
// torsional spring (rad). Four doubles, kept per ball and race.
struct ContactHistory3d {
  double *shear;  // 3 components
  double *twist;  // 1
};

struct RaceContactResult3d {
  bool touching = false;
  bool off_groove = false;  // touching with cos(alpha) <= 0: the ball has left the groove
  double delta = 0, fn = 0;
  double ft_rolling = 0;     // tangential force along the rolling direction axis x e_rho (N)
  double rolling_speed = 0;  // the surfaces' mean speed past the contact point along the
                             // rolling direction: the entrainment speed u of the film (m/s)
  double cos_alpha = 1, sin_alpha = 0;
  Vec3 normal;             // unit, from the groove's curvature centre to the ball centre
  Vec3 point;              // contact point (middle of the overlap)
  Vec3 force_on_ball;      // total (N); the ring gets the opposite at `point`
  Vec3 torque_on_ball;     // about the ball centre (N m)
  Vec3 torque_on_ring;     // about the ring centre, from this ball (N m)
  double spin_moment = 0;  // about the normal, on the ball (N m)
};

// `recess`: how far the surface falls away under the contact (a pit), m. The history is
// advanced by the relative motion times dt when update_history, and reset when not touching.
inline RaceContactResult3d race_contact_3d(const RaceContactModel3d &m, const RingMotion3d &ring,
                                           const BallState3d &b, double recess, double dt,
                                           bool update_history, ContactHistory3d hist)
{
  RaceContactResult3d r;
  const bool inner = m.groove.side == RaceSide::Inner;
  TorusGroove g = m.groove;
  g.centre_radius += inner ? ring.radius_shift : -ring.radius_shift;
  const Vec3 local = ring.tilted ? ring.tilt.apply_transpose(b.x - ring.centre) : b.x - ring.centre;
  const TorusContactGeometry geo = torus_geometry(g, local);
  const double delta = geo.delta - recess;
  r.delta = delta;
  auto reset = [&hist]() {
    hist.shear[0] = hist.shear[1] = hist.shear[2] = 0.0;
    *hist.twist = 0.0;
  };
  if (!geo.defined || !(delta > 0.0)) {
    reset();
    return r;
  }
  r.touching = true;
  r.cos_alpha = geo.cos_alpha;
  r.sin_alpha = geo.sin_alpha;
  if (!(geo.cos_alpha > 0.0)) {
    r.off_groove = true;  // the caller stops the run: no force is defined past the circle
    reset();
    return r;
  }
  const Vec3 n = ring.tilted ? ring.tilt.apply(geo.m) : geo.m;
  r.normal = n;
  const double arm = m.groove.ball_radius - 0.5 * delta;
  const Vec3 lever = arm * n;
  r.point = b.x + lever;

  // Velocities of the two material points at the contact.
  const Vec3 e_rho = ring.tilted ? ring.tilt.apply(geo.e_rho) : geo.e_rho;
  const Vec3 from_centre = r.point - ring.centre;
  const double radial = inner ? ring.radius_rate : -ring.radius_rate;
  const Vec3 vb = b.v + cross(b.omega, lever);
  const Vec3 vr = ring.velocity + cross(ring.omega, from_centre) + radial * e_rho;
  const Vec3 vrel = vb - vr;
  const double vn = dot(vrel, n);  // d(delta)/dt: the ball's point moves into the race along n
  const Vec3 vt = vrel - vn * n;

  // Normal: exact elliptic Hertz at this contact angle + restitution damping.
  const HertzMechanics h = m.hertz.mechanics(geo.cos_alpha);
  const double sq = std::sqrt(delta);
  const double q = h.K * delta * sq;
  const double gamma_n = damping_coefficient(m.beta, 1.5 * h.K * sq, b.mass);
  r.fn = std::max(0.0, q + gamma_n * vn);

  // Tangential spring, projected into this step's tangent plane: the plane turns with the ball's
  // orbit, w_c dt a step (2e-4 rad at 500 rad/s and 1 us), and the projection loses a fraction
  // (w_c dt)^2 / 2 of its length, far below what rolling relaxes.
  Vec3 s{hist.shear[0], hist.shear[1], hist.shear[2]};
  s = s - dot(s, n) * n;
  // Rolling speed: the two surfaces' mean speed past the contact point, in the tangent plane;
  // the relaxation over this step, implicit. The contact point travels with the ball's orbit about
  // the ring's axis: the ball centre's velocity turned by the orbit's rate over the lever (its own
  // spin does not move the point).
  const Vec3 axis = ring.tilted ? ring.tilt.column(2) : Vec3{0.0, 0.0, 1.0};
  const Vec3 from_axis = b.x - ring.centre - dot(b.x - ring.centre, axis) * axis;
  const double r2 = dot(from_axis, from_axis);
  const double orbit = r2 > 0.0 ? dot(cross(from_axis, b.v), axis) / r2 : 0.0;
  const Vec3 vp = b.v + orbit * cross(axis, lever);
  const Vec3 pass = 0.5 * ((vb - vp) + (vr - vp));
  const double roll = norm(pass - dot(pass, n) * n);
  const double length = h.length_coef * sq;  // 2b at the elastic load
  const double relax = update_history && length > 0.0 ? 1.0 / (1.0 + roll * dt / length) : 1.0;
  if (update_history) s = relax * (s + dt * vt);
  const double kt = h.kt_coef * sq;
  const double gamma_t = damping_coefficient(m.beta, kt, b.mass);
  Vec3 ft = -kt * s - gamma_t * vt;
  const double cap = m.friction * r.fn;
  const double ft_len = norm(ft);
  if (ft_len > cap) {
    // Sliding: on the Coulomb cone, the spring holds what it can carry.
    ft = (ft_len > 0.0 ? cap / ft_len : 0.0) * ft;
    s = kt > 0.0 ? (-1.0 / kt) * ft : Vec3{};
  }
  hist.shear[0] = s.x;
  hist.shear[1] = s.y;
  hist.shear[2] = s.z;

  // Spin about the contact normal: torsional spring capped by the full-sliding moment.
  const double w_rel = dot(b.omega - ring.omega, n);
  double twist = *hist.twist;
  if (update_history) twist = relax * (twist + dt * w_rel);
  const double k_twist = h.torsion_coef * delta * sq;
  const double gamma_w = damping_coefficient(m.beta, k_twist, b.inertia);
  double spin = -k_twist * twist - gamma_w * w_rel;
  const double spin_cap = m.friction * h.spin_cap_coef * delta * delta;  // at the elastic load
  if (std::fabs(spin) > spin_cap) {
    spin = std::copysign(spin_cap, spin);
    twist = k_twist > 0.0 ? -spin / k_twist : 0.0;
  }
  *hist.twist = twist;
  r.spin_moment = spin;

  const Vec3 e_roll = cross(axis, e_rho);
  r.ft_rolling = dot(ft, e_roll);
  r.rolling_speed = std::fabs(dot(pass, e_roll));
  r.force_on_ball = -r.fn * n + ft;
  r.torque_on_ball = cross(lever, ft) + spin * n;
  r.torque_on_ring = cross(from_centre, -r.force_on_ball) - spin * n;
  return r;
}

}  // namespace ohmdem

#endif
