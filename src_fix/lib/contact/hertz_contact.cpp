// SPDX-License-Identifier: GPL-2.0-or-later
// Hertz elliptic contact kernel. Equations and sources: doc/methods/hertz_contact.md.
#include "contact/hertz_contact.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/constants.h"
#include "common/fast_cbrt.h"

namespace ohmdem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string format_error(const char *what, double value, const char *why)
{
  char buf[320];
  std::snprintf(buf, sizeof buf, "HertzContact: %s = %.6g %s", what, value, why);
  return buf;
}

void require_positive_finite(const char *what, double value, const char *why)
{
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(format_error(what, value, why));
}

}  // namespace

CurvatureSums ball_inner_race(double r_ball, double r_race, double r_groove)
{
  return {1 / r_ball + 1 / r_race, 1 / r_ball - 1 / r_groove};
}

CurvatureSums ball_outer_race(double r_ball, double r_race, double r_groove)
{
  return {1 / r_ball - 1 / r_race, 1 / r_ball - 1 / r_groove};
}

CurvatureSums sphere_sphere(double r1, double r2)
{
  return {1 / r1 + 1 / r2, 1 / r1 + 1 / r2};
}

CurvatureSums sphere_flat(double r)
{
  return {1 / r, 1 / r};
}

double effective_modulus(double E1, double nu1, double E2, double nu2)
{
  return 1 / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
}

double effective_shear_modulus(double E1, double nu1, double E2, double nu2)
{
  return 1 / (2 * (2 - nu1) * (1 + nu1) / E1 + 2 * (2 - nu2) * (1 + nu2) / E2);
}

// Arithmetic-geometric mean (Abramowitz & Stegun 17.6): K = pi/(2 a_N),
// E = K (1 - sum_n 2^(n-1) c_n^2), c_0 = k, c_{n+1} = c_n^2/(4 a_{n+1}) (no cancellation).
// Tracking q_n = c_n^2/m gives D = (K - E)/m = K sum_n 2^(n-1) q_n without cancellation.
CompleteElliptic complete_elliptic(double kp)
{
  if (!(kp > 0)) return {kInf, 1.0, kInf};          // m = 1: K, D diverge logarithmically
  if (kp >= 1) return {kPi / 2, kPi / 2, kPi / 4};  // m = 0 (circle)
  const double m = (1 - kp) * (1 + kp);
  double a = 1, g = kp, c2 = m, q = 1, pow2 = 0.5;
  double sum_q = pow2 * q;
  for (int n = 0; n < 64; ++n) {
    const double a_next = 0.5 * (a + g);
    const double f = c2 / (16 * a_next * a_next);  // c_{n+1}^2 / c_n^2
    g = std::sqrt(a * g);
    a = a_next;
    c2 *= f;
    q *= f;
    pow2 *= 2;
    sum_q += pow2 * q;
    if (pow2 * q <= 1e-18 * sum_q) break;
  }
  const double K = kPi / (2 * a);
  return {K, K * (1 - m * sum_q), K * sum_q};
}

// kappa = a/b solves the Hertz equation F(rho) = [(k^2+1)E - 2K]/[(k^2-1)E] (Hamrock &
// Brewe 1983; Harris). With D = (K-E)/m and k^2 - 1 = m k^2 it is equivalent to Johnson's
// eq 4.39 ratio form  1 + max/min = k^2 E(m)/D(m),  which has no 0/0 at k = 1 and is
// increasing in k. Solved by bisection on t = ln(k) to full double precision: it runs
// once per contact type, so robustness matters more than speed.
double exact_ellipticity(CurvatureSums s)
{
  require_positive_finite("curvature sum A", s.A, "1/m must be positive and finite");
  require_positive_finite("curvature sum B", s.B, "1/m must be positive and finite");
  const double ratio = std::fmax(s.A, s.B) / std::fmin(s.A, s.B);
  require_positive_finite("curvature ratio max(A,B)/min(A,B)", ratio, "is too large");
  if (ratio == 1) return 1;
  const double target = 1 + ratio;
  auto h = [](double t) {
    const double kp = std::exp(-t);
    const CompleteElliptic ce = complete_elliptic(kp);
    return ce.E / (kp * kp * ce.D);  // kappa^2 E / D, kp = 1/kappa
  };
  double lo = 0, hi = 0.5 * std::log(target) + 1;
  for (int i = 0; i < 64 && h(hi) < target; ++i) {
    lo = hi;
    hi *= 2;
  }
  for (int i = 0; i < 400; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (h(mid) < target ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

double greenwood_radius(CurvatureSums s)
{
  return std::cbrt(2 / (s.A * s.B * (s.A + s.B)));
}

HertzContact::HertzContact(CurvatureSums sums, double E_eff, AreaModel model)
    : sums_(sums), E_eff_(E_eff), model_(model)
{
  const char *why =
      "1/m is not positive: the bodies must touch at a point, convex in that plane (e.g. a "
      "groove or outer race radius must be larger than the ball radius)";
  require_positive_finite("curvature sum A", sums.A, why);
  require_positive_finite("curvature sum B", sums.B, why);
  require_positive_finite("effective modulus E_eff", E_eff, "Pa must be positive and finite");

  // Exact Hertz (Hamrock/Harris form): E' = 2 E_eff, Sigma = A + B,
  // a^3 = 6 k^2 E(m) Q/(pi Sigma E'), b^3 = 6 E(m) Q/(pi k Sigma E'),
  // delta = K(m) [(9 Sigma/(2 E(m))) (Q/(pi k E'))^2]^(1/3)  =>  Q = K_hertz delta^1.5.
  kappa_exact_ = exact_ellipticity(sums);
  const CompleteElliptic ce = complete_elliptic(1 / kappa_exact_);
  const double sigma = sums.A + sums.B, Ep = 2 * E_eff, k = kappa_exact_;
  K_hertz_ = kPi * k * Ep * std::sqrt(2 * ce.E / (9 * sigma * ce.K * ce.K * ce.K));
  if (model == AreaModel::Exact) {
    kappa_ = k;
    a_coef_ = std::cbrt(6 * k * k * ce.E / (kPi * sigma * Ep));
    b_coef_ = std::cbrt(6 * ce.E / (kPi * k * sigma * Ep));
  } else {
    // Greenwood (1985), the paper's eqs 2-5: c = (3 Q r_eff/(4 E_eff))^(1/3), c^2 = a b,
    // a/b = (max/min)^(2/3).
    kappa_ = std::pow(std::fmax(sums.A, sums.B) / std::fmin(sums.A, sums.B), 2.0 / 3.0);
    const double c_coef = std::cbrt(3 * greenwood_radius(sums) / (4 * E_eff));
    a_coef_ = c_coef * std::sqrt(kappa_);
    b_coef_ = c_coef / std::sqrt(kappa_);
  }
}

double HertzContact::approach(double force) const
{
  if (!(force > 0)) return 0;
  const double r = std::cbrt(force / K_hertz_);  // cbrt first: no overflow of force^2
  return r * r;
}

ContactEllipse HertzContact::ellipse(double fn) const
{
  ContactEllipse e;
  if (!(fn > 0)) return e;
  const double q = cbrt_fast(fn);  // per contact and step: the inline root
  e.a = a_coef_ * q;
  e.b = b_coef_ * q;
  e.c = std::sqrt(e.a * e.b);
  e.area = kPi * e.a * e.b;
  return e;
}

}  // namespace ohmdem
