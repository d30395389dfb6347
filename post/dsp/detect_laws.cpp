// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/detect_laws.h"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace ohmdem::post {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Anscombe-Glynn constants for n values: mean and variance of b2, and A.
struct AnscombeGlynn {
  double mean, sd, a;
  explicit AnscombeGlynn(double n)
  {
    mean = 3 * (n - 1) / (n + 1);
    sd = std::sqrt(24 * n * (n - 2) * (n - 3) / ((n + 1) * (n + 1) * (n + 3) * (n + 5)));
    const double sqrt_beta1 = 6 * (n * n - 5 * n + 2) / ((n + 7) * (n + 9)) *
                              std::sqrt(6 * (n + 3) * (n + 5) / (n * (n - 2) * (n - 3)));
    a = 6 + 8 / sqrt_beta1 * (2 / sqrt_beta1 + std::sqrt(1 + 4 / (sqrt_beta1 * sqrt_beta1)));
  }
};

// Greenwood's statistic G = m sum D_i^2 (D uniform on the m-simplex): E G^r from the Dirichlet
// moments E prod D_i^{a_i} = Gamma(m) prod a_i! / Gamma(m + sum a_i).
struct ShiftedGamma {
  double k = 0, theta = 0, loc = 0;
};

ShiftedGamma greenwood_law(double m)
{
  const double e1 = 2 * m / (m + 1);
  const double e2 = m * m * (4 * m + 20) / ((m + 1) * (m + 2) * (m + 3));
  const double e3 = m * m * m * (720 + 144 * (m - 1) + 8 * (m - 1) * (m - 2)) /
                    ((m + 1) * (m + 2) * (m + 3) * (m + 4) * (m + 5));
  const double var = e2 - e1 * e1;
  const double mu3 = e3 - 3 * e1 * e2 + 2 * e1 * e1 * e1;
  const double sd = std::sqrt(var);
  const double skew = mu3 / (var * sd);
  ShiftedGamma g;
  g.k = 4 / (skew * skew);
  g.theta = sd * skew / 2;
  g.loc = e1 - g.k * g.theta;
  return g;
}

}  // namespace

double student_t_sf(double t, double nu)
{
  return boost::math::cdf(boost::math::complement(boost::math::students_t(nu), t));
}

double check_probability(double p, const char *what)
{
  if (!(p > 0 && p < 1)) throw SettingError(std::string(what) + ": probability must be in (0, 1)");
  return p;
}

double normal_sf(double z)
{
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

double normal_isf(double p)
{
  check_probability(p, "normal_isf");
  return boost::math::quantile(boost::math::complement(boost::math::normal(), p));
}

double student_t_isf(double p, double nu)
{
  check_probability(p, "student_t_isf");
  if (!(nu > 0)) throw Error("student_t_isf: degrees of freedom must be > 0");
  return boost::math::quantile(boost::math::complement(boost::math::students_t(nu), p));
}

double kurtosis_z(double b2, double n)
{
  if (!(n >= 5)) return kNaN;
  const AnscombeGlynn ag(n);
  const double x = (b2 - ag.mean) / ag.sd;
  const double term1 = 1 - 2 / (9 * ag.a);
  const double denom = 1 + x * std::sqrt(2 / (ag.a - 4));
  // denom <= 0 (b2 far below its mean): the transform is undefined; scipy then returns a
  // meaningless sign-flipped z. For a one-sided test of a high kurtosis it is -infinity.
  if (!(denom > 0)) return -std::numeric_limits<double>::infinity();
  const double term2 = std::cbrt((1 - 2 / ag.a) / denom);
  return (term1 - term2) / std::sqrt(2 / (9 * ag.a));
}

double kurtosis_sf(double b2, double n)
{
  return normal_sf(kurtosis_z(b2, n));
}

double kurtosis_threshold(double n, double p)
{
  check_probability(p, "kurtosis_threshold");
  if (!(n >= 5)) return kNaN;
  const AnscombeGlynn ag(n);
  const double term1 = 1 - 2 / (9 * ag.a);
  const double term2 = term1 - normal_isf(p) * std::sqrt(2 / (9 * ag.a));
  if (!(term2 > 0)) return std::numeric_limits<double>::infinity();
  const double denom = (1 - 2 / ag.a) / (term2 * term2 * term2);
  return ag.mean + ag.sd * (denom - 1) / std::sqrt(2 / (ag.a - 4));
}

double crest_sf(double u, double n)
{
  return -std::expm1(n * std::log1p(-2 * normal_sf(u)));
}

double crest_threshold(double n, double p)
{
  check_probability(p, "crest_threshold");
  return normal_isf(-std::expm1(std::log1p(-p) / n) / 2);
}

double spectral_kurtosis_sf(double sk, double m)
{
  const ShiftedGamma g = greenwood_law(m);
  const double y = (sk + 2 - g.loc) / g.theta;
  if (!(y > 0)) return 1;
  const double v = 1 / (9 * g.k);
  return normal_sf((std::cbrt(y / g.k) - (1 - v)) / std::sqrt(v));
}

double spectral_kurtosis_threshold(double m, double p)
{
  check_probability(p, "spectral_kurtosis_threshold");
  const ShiftedGamma g = greenwood_law(m);
  const double v = 1 / (9 * g.k);
  const double c = 1 - v + normal_isf(p) * std::sqrt(v);
  return g.loc + g.theta * g.k * std::max(c, 0.0) * c * c - 2;
}

}  // namespace ohmdem::post
