// SPDX-License-Identifier: GPL-2.0-or-later
// Hertz contact geometry of two elastic bodies with principal curvatures (elliptic contact),
// plain C++ (no LIGGGHTS types). Physics and sources: doc/methods/hertz_contact.md.
//
// Conventions: SI units; curvature sums are FULL sums of both bodies' curvatures (1/R, not
// 1/(2R)), convex positive, concave negative.
#ifndef OHMDEM_HERTZ_CONTACT_H
#define OHMDEM_HERTZ_CONTACT_H

#include <cmath>

namespace ohmdem {

enum class AreaModel { Greenwood, Exact };

// Full curvature sums (1/m) in the two principal planes.
struct CurvatureSums {
  double A;
  double B;
};
// A = 1/rb + 1/R_race (rolling plane), B = 1/rb - 1/R_groove (groove plane).
CurvatureSums ball_inner_race(double r_ball, double r_race, double r_groove);
// A = 1/rb - 1/R_race (the outer race is concave in the rolling plane), B = 1/rb - 1/R_groove.
CurvatureSums ball_outer_race(double r_ball, double r_race, double r_groove);
CurvatureSums sphere_sphere(double r1, double r2);  // both 1/r1 + 1/r2
CurvatureSums sphere_flat(double r);                // both 1/r

// E*: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 (Johnson eq 4.22).
double effective_modulus(double E1, double nu1, double E2, double nu2);
// G*: 1/G* = 2(2-nu1)(1+nu1)/E1 + 2(2-nu2)(1+nu2)/E2 (LIGGGHTS' convention).
double effective_shear_modulus(double E1, double nu1, double E2, double nu2);

// Complete elliptic integrals of parameter m = 1 - kp^2, from the complementary modulus
// kp = sqrt(1 - m) in (0, 1] so that m -> 1 (very elongated contacts) keeps full precision.
// D = (K - E)/m is returned without cancellation (it is finite, pi/4, at m = 0).
struct CompleteElliptic {
  double K;
  double E;
  double D;
};
CompleteElliptic complete_elliptic(double kp);

// Ellipticity a/b >= 1 of the exact Hertz contact (Hamrock/Harris equation, see the .md);
// 1 exactly when A == B. Throws std::invalid_argument unless A, B are finite and > 0.
double exact_ellipticity(CurvatureSums sums);
// Greenwood's (1985) equivalent radius r_eff = (A*B*(A+B)/2)^(-1/3): c^2 = a*b.
double greenwood_radius(CurvatureSums sums);

struct ContactEllipse {
  double a = 0;     // semi-major axis (m), lies in the plane of the SMALLER curvature sum
  double b = 0;     // semi-minor axis (m), lies in the plane of the LARGER curvature sum
  double c = 0;     // sqrt(a*b)
  double area = 0;  // pi*a*b
};

// Everything that depends on geometry only is precomputed in the constructor (once per
// contact type); the per-step calls are a few flops. The contact area comes from the normal
// force (rigid Hertz areas, the paper's approach); the force law Q = K delta^1.5 is always
// the exact Hertz one.
class HertzContact {
 public:
  // Throws std::invalid_argument naming the problem if A <= 0 or B <= 0 (e.g. a groove
  // radius not larger than the ball radius), or E_eff <= 0, or any of them not finite.
  HertzContact(CurvatureSums sums, double E_eff, AreaModel model = AreaModel::Exact);

  double ellipticity() const { return kappa_; }           // a/b of the chosen model
  double stiffness_constant() const { return K_hertz_; }  // exact K in Q = K delta^1.5
  // force() and normal_stiffness() are inline: they run for every contact at every step, and
  // inlined together they share one sqrt(delta). !(delta > 0) also maps NaN to "no contact",
  // so nothing downstream sees a NaN.
  double force(double delta) const  // 0 for delta <= 0 (or NaN)
  {
    return delta > 0 ? K_hertz_ * delta * std::sqrt(delta) : 0;
  }
  double normal_stiffness(double delta) const  // dQ/ddelta, 0 for delta <= 0
  {
    return delta > 0 ? 1.5 * K_hertz_ * std::sqrt(delta) : 0;
  }
  double approach(double force) const;      // 0 for Q <= 0 (or NaN)
  ContactEllipse ellipse(double fn) const;  // all zero for fn <= 0 (or NaN)
  AreaModel model() const { return model_; }

  // Additions.
  CurvatureSums sums() const { return sums_; }
  double kappa_exact() const { return kappa_exact_; }  // exact a/b, whatever the model
  double E_eff() const { return E_eff_; }
  // True if the major axis a lies in the plane of A (i.e. A <= B).
  bool major_axis_in_A_plane() const { return sums_.A <= sums_.B; }

 private:
  CurvatureSums sums_;
  double E_eff_;
  AreaModel model_;
  double kappa_exact_;
  double kappa_;    // ellipticity of the chosen model
  double K_hertz_;  // exact Hertz stiffness constant (N/m^1.5)
  double a_coef_;   // a = a_coef_ * Q^(1/3), b = b_coef_ * Q^(1/3)
  double b_coef_;
};

}  // namespace ohmdem

#endif
