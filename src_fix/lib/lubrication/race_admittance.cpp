// SPDX-License-Identifier: GPL-2.0-or-later
// A race's contacts with its constants computed once; see race_admittance.h.
#include "lubrication/race_admittance.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>

#include "common/constants.h"
#include "common/estrin.h"
#include "common/fast_cbrt.h"
#include "common/fast_erfc.h"
#include "common/fast_exp_log.h"
#include "lubrication/exp_small.h"
#include "lubrication/fraction_bounds.h"
#include "lubrication/gap_forms.h"

namespace ohmdem::lubrication {

using gap_forms::form_mean;
using gap_forms::FormMean;

namespace {
const double kSqrtHalf = std::sqrt(0.5);
}  // namespace

RaceAdmittance::RaceAdmittance(const RaceInput &in) : in_(in)
{
  // The films' prefactors and ellipticity factors, k = a/b (load-independent).
  const Film pre = film_prefactors(in.eta, in.e_prime, in.rx, in.alpha);
  const Film ell = ellipticity_factors(in.a_coef / in.b_coef);
  central_ = pre.central;
  minimum_ = pre.minimum;
  ell_central_ = ell.central;
  ell_minimum_ = ell.minimum;
  area_coef_ = kPi * in.a_coef * in.b_coef;
  // hertz_mean_permittivity's nodes; (d + 2 K n)/(d - K n) with d = 1 + 1.7 q, n = 1 + 2.3 q.
  const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                       0.9602898564975363};
  const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                       0.1012285362903763};
  for (int i = 0; i < 4; ++i) {
    t_[2 * i] = 0.5 * (1.0 - x[i]);
    t_[2 * i + 1] = 0.5 * (1.0 + x[i]);
    wt_[2 * i] = w[i] * t_[2 * i];
    wt_[2 * i + 1] = w[i] * t_[2 * i + 1];
  }
  // As partial fractions, eps = be/de + (al - be ga/de)/(ga + de q): one division per node.
  const double kcm = (in.eps_r - 1.0) / (in.eps_r + 2.0);
  const double al = 1.0 + 2.0 * kcm, be = 1.7 + 4.6 * kcm, ga = 1.0 - kcm, de = 1.7 - 2.3 * kcm;
  ga_ = ga;
  double sum_wt = 0.0;
  for (int i = 0; i < 8; ++i) {
    sum_wt += wt_[i];
    dt_[i] = de * t_[i];
  }
  eps_const_ = be / de * sum_wt;
  eps_pole_ = al - be * ga / de;
  // The same sum as one fraction P(q)/Q(q), Q = prod(ga + dt_i q), P = sum wt_i prod_(j != i):
  // one division instead of eight. With de >= 0 (eps_r <= 9.5) every coefficient is positive and
  // q >= 0, so the sums (Estrin's form, common/estrin.h) add positive terms only (a few ulp);
  // else the eight divisions.
  rational_ = de >= 0.0;
  // The coefficients (constant term first) of the product of (ga + dt_j q) over j != skip.
  const auto product = [&](int skip) {
    std::array<double, 9> c{};
    c[0] = 1.0;
    int degree = 0;
    for (int j = 0; j < 8; ++j) {
      if (j == skip) continue;
      ++degree;
      for (int k = degree; k >= 1; --k) c[k] = c[k] * ga + c[k - 1] * dt_[j];
      c[0] *= ga;
    }
    return c;
  };
  qc_ = product(-1);
  for (int i = 0; i < 8; ++i) {
    const std::array<double, 9> c = product(i);
    for (int k = 0; k < 8; ++k) pc_[k] += wt_[i] * c[k];
  }
  // The Hertz zone's peak pressure (GPa), 1.5 fn/(pi a b) 1e-9 = q0_coef_ fn^(1/3).
  q0_coef_ = 1.5e-9 / area_coef_;
  // The gap integral's race terms.
  p_ = 2.0 * in.rx;
  q_ = 2.0 * in.ry;
  r2_ = in.r_wet * in.r_wet;
  sqrt_p_ = std::sqrt(p_);
  sqrt_q_ = std::sqrt(q_);
  const FormMean pq = form_mean(sqrt_p_, sqrt_q_);
  pq_s_ = pq.s;
  pq_y_ = pq.y;
  // The Hertz ellipse's form mean, of (sqrt(2 rx)/b, sqrt(2 ry)/a): a and b scale with
  // fn^(1/3), so its s is hertz_s_ / fn^(1/3) and its y a race constant.
  sp_coef_ = sqrt_p_ / in.b_coef;
  sq_coef_ = sqrt_q_ / in.a_coef;
  const FormMean hz = form_mean(sp_coef_, sq_coef_);
  hertz_s_ = hz.s / pq_s_;
  hertz_y_ = hz.y / pq_y_;
  inv_sigma_ = 1.0 / in.sigma;
  inv_resistivity_ = 1.0 / in.resistivity;
  scale_ = kEpsilon0 * in.eps_r * std::sqrt(in.rx * in.ry) * 2.0 * kPi;
  splat_constants(*this);
  static std::atomic<std::uint64_t> races{0};
  serial_ = ++races;
}

void RaceAdmittance::contact(double fn, double speed, double g_dry, double recess,
                             ContactAdmittance &c) const
{
  const bool moving = speed > 0.0 && fn > 0.0;
  const double ls = moving ? log_fast(speed) : 0.0, lw = moving ? log_fast(fn) : 0.0;
  // fn^(1/3) from the film's logarithm where it has one (an exponential instead of the cube
  // root's three divisions; within ~2e-16 of it), else the cube root.
  const double cb = moving ? exp_fast(lw * (1.0 / 3.0)) : cbrt_fast(fn);
  const double a = in_.a_coef * cb, b = in_.b_coef * cb;  // HertzContact::ellipse
  c.film = Film{};
  c.c_hertz = 0.0;
  if (moving) {
    const double central_power = exp_fast(0.67 * ls - 0.067 * lw);
    c.film.central = central_ * central_power * ell_central_;
    // h_min / h_c = (its prefactors) exp(0.01 ls - 0.006 lw): a small argument, a short series.
    const double z = 0.01 * ls - 0.006 * lw;
    c.film.minimum =
        minimum_ *
        (std::fabs(z) < 0.25 ? central_power * exp_small(z) : exp_fast(0.68 * ls - 0.073 * lw)) *
        ell_minimum_;
  }
  c.lambda = c.film.minimum * inv_sigma_;  // film_parameter, by the reciprocal
  c.gap = c.film.minimum + recess;
  c.g_dry = g_dry;
  const double area = area_coef_ * cb * cb;  // pi a b
  const double h = c.film.central + recess;
  const bool film = h > 0.0 && area > 0.0;
  const double area_h = film ? area / h : 0.0;
  const double leak = area_h * inv_resistivity_;
  // The metallic fraction, or 0 when it cannot matter (race_admittance.h).
  const double xm = (recess > 0.0 ? c.gap * inv_sigma_ : c.lambda) * kSqrtHalf;
  // (fraction_bounds.h; 2^-54 needs x > 5.9: below 5.5 the bound is not worth its
  // exponential.) From x = 6 the cheap bound first, then the bound itself where that does not
  // settle it (the same decision: the cheap one is never smaller), unless it cannot pass.
  namespace fb = fraction_bounds;
  bool negligible = false, hopeless = false;
  if (xm > 5.5) {
    const double k = fb::exponent(xm);
    if (xm >= 6.0) negligible = fb::negligible(fb::cheap(k), g_dry, leak);
    hopeless = !negligible && fb::cannot_pass(xm, k, g_dry, leak);
    if (!negligible && !hopeless) negligible = fb::negligible(fb::bound(xm), g_dry, leak);
  }
  c.metallic = negligible ? 0.0 : erfc_fast(xm);
  const double free = 1.0 - c.metallic;
  c.g = c.metallic * g_dry;
  if (film && free > 0.0) {
    const double q0 = q0_coef_ * cb;  // Hertz peak pressure (GPa), 1.5 fn / (pi a b)
    c.c_hertz = free * kEpsilon0 * permittivity(q0) * area_h;
    c.g += free * leak;
  }
  // gap_capacitance's closed form while the wetted circle holds the ellipse.
  const double h0 = std::max(c.film.central, in_.sigma) + recess;
  if (!(in_.r_wet > a && in_.r_wet > b && a > 0.0 && b > 0.0)) {
    c.c_outer = gap_capacitance(GapGeometry{h0, in_.rx, in_.ry, a, b, in_.r_wet}, in_.eps_r);
    return;
  }
  const FormMean out = form_mean(std::sqrt(h0 * p_ + r2_), std::sqrt(h0 * q_ + r2_));
  const double inv_cb = 1.0 / cb, sp = sp_coef_ * inv_cb, sq = sq_coef_ * inv_cb;
  const FormMean in = form_mean(std::sqrt(h0 * sp * sp + 1.0), std::sqrt(h0 * sq * sq + 1.0));
  // The Hertz ellipse's form mean is hertz_s_ / cb with the race's y (the constructor).
  const double x = out.s * hertz_s_ * inv_cb / in.s, y = out.y * hertz_y_ / in.y;
  c.c_outer = scale_ * (2.0 * log_fast(x) + gap_forms::aliasing(y, log_fast));
}

// The pressure-raised permittivity averaged over the Hertz zone (hertz_mean_permittivity's
// 8-point rule) at the peak pressure q0 (GPa).
double RaceAdmittance::permittivity(double q0) const
{
  if (rational_) {
    const double num = estrin::polynomial<8>(pc_.data(), q0),
                 den = estrin::polynomial<9>(qc_.data(), q0);
    return eps_const_ + eps_pole_ * (num / den);
  }
  double sum = 0.0;
  for (int i = 0; i < 8; ++i) sum += wt_[i] / (ga_ + q0 * dt_[i]);
  return eps_const_ + eps_pole_ * sum;
}

double RaceAdmittance::idle(double gap) const
{
  const double h0 = std::max(gap, in_.sigma);
  const FormMean out = form_mean(std::sqrt(h0 * p_ + r2_), std::sqrt(h0 * q_ + r2_));
  const double x = out.s / (pq_s_ * std::sqrt(h0)), y = out.y / pq_y_;
  return scale_ * (2.0 * log_fast(x) + gap_forms::aliasing(y, log_fast));
}

}  // namespace ohmdem::lubrication
