// SPDX-License-Identifier: GPL-2.0-or-later
// A bearing raceway in three dimensions (plain C++, no LIGGGHTS types): the torus swept about
// the ring's axis by its groove's curvature-centre circle, and the exact elliptic Hertz contact
// of a ball in it at the contact angle the geometry gives. doc/methods/bearing_3d.md.
//
// Ring frame: z along the ring's axis, origin at the ring's centre. The groove's curvature
// centres lie on the circle of radius rho_c at height z_c; the groove surface is the torus of
// tube radius Rc about that circle. A ball of radius r whose centre lies at distance d from the
// circle touches the groove when d + r > Rc: the approach is delta = d + r - Rc, along the
// line from the nearest point P of the circle (in the ball's meridian plane) to the ball's
// centre. The contact angle alpha is that line's angle with the radial plane: the contact
// point is at the ball centre + (r - delta/2) m, m = (ball centre - P)/d.
//
// Sign of alpha: the inner ring's curvature centre P_i and the outer one's P_o of a ball that
// touches both satisfy P_i - P_o = |P_i - P_o| (cos alpha e_rho + sin alpha e_z) (Harris'
// construction): a ball pressed by an inner ring pushed along +z has alpha > 0 on both races.
//
// Curvature sums at alpha (full sums, convex positive, Harris' "rho" of the ball and race):
// rolling (circumferential) plane A = 1/r + s cos(alpha)/rho_S (Meusnier: the parallel circle
// of radius rho_S through the contact point, s = +1 inner, -1 outer), groove plane
// B = 1/r - 1/Rc. rho_S is the distance of the race surface point on the contact line from
// the axis: rho_c - Rc cos(alpha) (inner), rho_c + Rc cos(alpha) (outer).
#ifndef OHMDEM_TORUS_RACE_H
#define OHMDEM_TORUS_RACE_H

#include <cmath>
#include <vector>

#include "contact/hertz_contact.h"
#include "contact/race_contact.h"
#include "contact/vec3.h"

namespace ohmdem {

struct TorusGroove {
  RaceSide side = RaceSide::Inner;
  double ball_radius = 0;    // r (m)
  double centre_radius = 0;  // rho_c: radius of the groove's curvature-centre circle (m)
  double centre_z = 0;       // z_c: its axial position in the ring frame (m)
  double groove_radius = 0;  // Rc (m), > r
};

struct TorusContactGeometry {
  bool defined = false;     // false: the ball centre is on the ring's axis or on the circle
  double delta = 0;         // approach (m); > 0 when touching
  Vec3 m;                   // unit vector from P to the ball centre (ring frame)
  Vec3 e_rho;               // unit radial direction of the ball's meridian plane (ring frame)
  double cos_alpha = 1;     // from the geometry; <= 0 means the ball passed the circle: impossible
  double sin_alpha = 0;     // signed (see the header)
  double point_radius = 0;  // rho_S (m)
};

// Ball centre `b` in the ring frame. Inline: it runs for every ball at every step.
inline TorusContactGeometry torus_geometry(const TorusGroove &g, Vec3 b)
{
  TorusContactGeometry t;
  const double rho = std::sqrt(b.x * b.x + b.y * b.y);
  if (!(rho > 0.0)) return t;
  t.e_rho = {b.x / rho, b.y / rho, 0.0};
  const double mr = rho - g.centre_radius, mz = b.z - g.centre_z;
  const double d = std::sqrt(mr * mr + mz * mz);
  if (!(d > 0.0)) return t;
  t.defined = true;
  const double m_rho = mr / d, m_z = mz / d;
  t.m = {m_rho * t.e_rho.x, m_rho * t.e_rho.y, m_z};
  t.delta = d + g.ball_radius - g.groove_radius;
  const bool inner = g.side == RaceSide::Inner;
  t.cos_alpha = inner ? -m_rho : m_rho;
  t.sin_alpha = inner ? -m_z : m_z;
  t.point_radius = g.centre_radius + g.groove_radius * m_rho;
  return t;
}

// The full curvature sums of the ball in the groove at contact angle alpha (cos_alpha given).
CurvatureSums torus_curvatures(const TorusGroove &g, double cos_alpha);

// Effective shear modulus of a twisted contact: 1/G_t = 1/G1 + 1/G2, G = E/(2(1+nu)).
double torsion_shear_modulus(double E1, double nu1, double E2, double nu2);

// The exact Hertz contact of a ball in the groove as a function of cos(alpha): everything that
// depends on the geometry alone, tabulated once (nodes of cos(alpha) over [0, 1]) from
// HertzContact's exact solution and interpolated by 4-point Lagrange polynomials (relative
// error below 1e-10, tests/lib/contact/test_torus_race.cpp), so that a step costs no elliptic
// integral and no root finding.
struct HertzAtAngle {
  double K = 0;           // Q = K delta^1.5 (N/m^1.5), exact
  double a1 = 0, b1 = 0;  // exact semi-axes at 1 N (m): a = a1 Q^(1/3) across the groove
  double a1_greenwood = 0, b1_greenwood = 0;  // Greenwood's (1985) semi-axes at 1 N (m)
  double kt_coef = 0;                         // Mindlin k_t = 8 G* sqrt(a b) = kt_coef sqrt(delta)
  double spin_coef = 0;     // full-sliding spin moment 3 mu Q a E(e)/8 = mu spin_coef Q^(4/3)
  double torsion_coef = 0;  // torsional stiffness (16/3) G_t (ab)^(3/2) = torsion_coef delta^1.5
};

// What the contact force needs at every step, derived from HertzAtAngle so that the step takes
// no cube root: with Q = K delta^1.5, Q^(1/3) = K^(1/3) sqrt(delta).
struct HertzMechanics {
  double K = 0;        // Q = K delta^1.5
  double kt_coef = 0;  // k_t = kt_coef sqrt(delta)
  double length_coef =
      0;  // the ellipse's length along the rolling direction, 2b = length_coef sqrt(delta)
  double spin_cap_coef = 0;  // the spin moment's cap at the elastic load, mu spin_cap_coef delta^2
  double torsion_coef = 0;   // k_twist = torsion_coef delta^1.5
};

class AngularHertz {
 public:
  // Throws std::invalid_argument (naming the problem) for a groove not larger than the ball,
  // a non-positive modulus or a geometry whose curvature sums are not positive.
  AngularHertz(const TorusGroove &groove, double E_eff, double G_eff, double G_torsion,
               int intervals = 512);
  // The exact values at cos_alpha, computed directly (slow: the reference the table follows).
  HertzAtAngle exact(double cos_alpha) const;
  // Interpolated (fast). cos_alpha is clamped to [0, 1].
  HertzAtAngle at(double cos_alpha) const
  {
    const double c = cos_alpha < 0.0 ? 0.0 : (cos_alpha > 1.0 ? 1.0 : cos_alpha);
    const double u = c * intervals_;
    int i = static_cast<int>(u);
    if (i < 1) i = 1;
    if (i > intervals_ - 2) i = intervals_ - 2;
    const double t = u - i;  // nodes i-1, i, i+1, i+2 at t = -1, 0, 1, 2
    const double w0 = -t * (t - 1.0) * (t - 2.0) / 6.0,
                 w1 = (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0;
    const double w2 = -(t + 1.0) * t * (t - 2.0) / 2.0, w3 = (t + 1.0) * t * (t - 1.0) / 6.0;
    const HertzAtAngle *n = &table_[i - 1];
    HertzAtAngle h;
    h.K = w0 * n[0].K + w1 * n[1].K + w2 * n[2].K + w3 * n[3].K;
    h.a1 = w0 * n[0].a1 + w1 * n[1].a1 + w2 * n[2].a1 + w3 * n[3].a1;
    h.b1 = w0 * n[0].b1 + w1 * n[1].b1 + w2 * n[2].b1 + w3 * n[3].b1;
    h.a1_greenwood = w0 * n[0].a1_greenwood + w1 * n[1].a1_greenwood + w2 * n[2].a1_greenwood +
                     w3 * n[3].a1_greenwood;
    h.b1_greenwood = w0 * n[0].b1_greenwood + w1 * n[1].b1_greenwood + w2 * n[2].b1_greenwood +
                     w3 * n[3].b1_greenwood;
    h.kt_coef = w0 * n[0].kt_coef + w1 * n[1].kt_coef + w2 * n[2].kt_coef + w3 * n[3].kt_coef;
    h.spin_coef =
        w0 * n[0].spin_coef + w1 * n[1].spin_coef + w2 * n[2].spin_coef + w3 * n[3].spin_coef;
    h.torsion_coef = w0 * n[0].torsion_coef + w1 * n[1].torsion_coef + w2 * n[2].torsion_coef +
                     w3 * n[3].torsion_coef;
    return h;
  }
  // HertzMechanics at cos_alpha, interpolated as at() (its own table: five values, not eight).
  HertzMechanics mechanics(double cos_alpha) const
  {
    const double c = cos_alpha < 0.0 ? 0.0 : (cos_alpha > 1.0 ? 1.0 : cos_alpha);
    const double u = c * intervals_;
    int i = static_cast<int>(u);
    if (i < 1) i = 1;
    if (i > intervals_ - 2) i = intervals_ - 2;
    const double t = u - i;
    const double w0 = -t * (t - 1.0) * (t - 2.0) / 6.0,
                 w1 = (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0;
    const double w2 = -(t + 1.0) * t * (t - 2.0) / 2.0, w3 = (t + 1.0) * t * (t - 1.0) / 6.0;
    const HertzMechanics *n = &mechanics_[i - 1];
    HertzMechanics h;
    h.K = w0 * n[0].K + w1 * n[1].K + w2 * n[2].K + w3 * n[3].K;
    h.kt_coef = w0 * n[0].kt_coef + w1 * n[1].kt_coef + w2 * n[2].kt_coef + w3 * n[3].kt_coef;
    h.length_coef = w0 * n[0].length_coef + w1 * n[1].length_coef + w2 * n[2].length_coef +
                    w3 * n[3].length_coef;
    h.spin_cap_coef = w0 * n[0].spin_cap_coef + w1 * n[1].spin_cap_coef + w2 * n[2].spin_cap_coef +
                      w3 * n[3].spin_cap_coef;
    h.torsion_coef = w0 * n[0].torsion_coef + w1 * n[1].torsion_coef + w2 * n[2].torsion_coef +
                     w3 * n[3].torsion_coef;
    return h;
  }
  // The ellipse of a contact at cos_alpha under the normal force fn, in either area model.
  ContactEllipse ellipse(double cos_alpha, double fn, AreaModel model) const;
  const TorusGroove &groove() const { return groove_; }
  double E_eff() const { return E_eff_; }

 private:
  TorusGroove groove_;
  double E_eff_, G_eff_, G_torsion_;
  int intervals_;
  std::vector<HertzAtAngle> table_;        // intervals_ + 1 nodes, cos(alpha) = k / intervals_
  std::vector<HertzMechanics> mechanics_;  // the same nodes
};

}  // namespace ohmdem

#endif
