// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/pulse_template.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bearing/defect_size.h"
#include "bearing/diagnose.h"
#include "bearing/race_sizing.h"
#include "bearing/template_angle.h"
#include "core/circular_index.h"
#include "core/constants.h"
#include "core/sampled_signal.h"
#include "dsp/detect_laws.h"
#include "dsp/pulses.h"

namespace ohmdem::post {

namespace {

// The runs' own differences (mix below): 2 % of the pulse, 5 us of timing.
constexpr double kModelRel = 0.02, kModelJitterS = 5e-6;

// Above this reduced chi-square at the best template (the runs' own differences allowed for) the
// bank does not describe the record. Fits of the study's records stay below 1 inside the bank;
// held-out outer pits between two of its angles reached 60 before the fundamental's removal.
constexpr double kMaxReducedChi2 = 10;

}  // namespace

void bank_grid(const TemplateBank &b, std::vector<double> &sizes, std::vector<double> &angles)
{
  sizes.clear();
  angles.clear();
  for (const PulseTemplate &t : b.templates) {
    if (t.y.size() < 8 || t.se.size() != t.y.size())
      throw std::invalid_argument("a template has fewer than 8 bins or no error per bin");
    sizes.push_back(t.size_deg);
    angles.push_back(t.angle_deg);
  }
  for (auto *v : {&sizes, &angles}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  if (sizes.size() < 2 || sizes.size() * angles.size() != b.templates.size())
    throw std::invalid_argument(
        "the templates must cover every size at every angle once (a full grid), with at least "
        "two sizes");
}

namespace {

// A template's first n bins and their variance in the fit.
struct Weighted {
  std::vector<double> y, var;
};

Weighted weighted(const PulseTemplate &t, std::size_t n, double jitter_bins)
{
  Weighted m{std::vector<double>(t.y.begin(), t.y.begin() + static_cast<long>(n)),
             std::vector<double>(n, 0.0)};
  // two runs of the scene differ by more than their passes' scatter (the ring's motion is not
  // repeated to the microsecond): a relative amplitude and a timing jitter (kModelRel,
  // kModelJitterS) per bin, so that the sharp edges and the peak, where the least of these
  // shows, do not outweigh the rest of the pulse
  for (std::size_t j = 0; j < n; ++j) {
    const double slope = 0.5 * (m.y[std::min(j + 1, n - 1)] - m.y[j > 0 ? j - 1 : 0]);
    m.var[j] = t.se[j] * t.se[j] + std::pow(kModelRel * m.y[j], 2) +
               std::pow(jitter_bins * slope, 2);
  }
  return m;
}

// chi2 of the record against m over the template's first n bins, the record shifted by `shift`
// bins (linear interpolation between its bins, circular), the best constant offset removed.
double chi2_at(const FoldedPulse &rec, const Weighted &m, std::size_t n, std::size_t entry,
               double shift)
{
  const std::size_t nb = rec.y.size();
  const double base = static_cast<double>(rec.entry) - static_cast<double>(entry) + shift;
  double sw = 0, swr = 0, swr2 = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double at = static_cast<double>(j) + base;
    const double fl = std::floor(at);
    const double u = at - fl;
    const std::size_t i0 = circular_index(static_cast<long>(fl), nb), i1 = (i0 + 1) % nb;
    const double yr = (1 - u) * rec.y[i0] + u * rec.y[i1];
    const double se = u < 0.5 ? rec.se[i0] : rec.se[i1];
    const double w = 1 / (se * se + m.var[j]);
    const double r = yr - m.y[j];
    sw += w;
    swr += w * r;
    swr2 += w * r * r;
  }
  return swr2 - swr * swr / sw;
}

// The least chi2 over shifts within +-reach bins (every bin, then the parabola's vertex).
std::pair<double, double> best_shift(const FoldedPulse &rec, const Weighted &m, std::size_t n,
                                     std::size_t entry, int reach)
{
  std::vector<double> c;
  for (int k = -reach; k <= reach; ++k) c.push_back(chi2_at(rec, m, n, entry, k));
  const auto i = static_cast<std::size_t>(std::min_element(c.begin(), c.end()) - c.begin());
  double best = c[i], shift = static_cast<double>(i) - reach;
  if (i > 0 && i + 1 < c.size()) {
    const double curv = c[i - 1] - 2 * c[i] + c[i + 1];
    if (curv > 0) {
      const double s = shift + 0.5 * (c[i - 1] - c[i + 1]) / curv;
      const double v = chi2_at(rec, m, n, entry, s);
      if (v < best) best = v, shift = s;
    }
  }
  return {best, shift};
}

// The profile's range under `limit`, refined between grid points by linear interpolation; lo
// NaN-free, hi NaN when the range reaches the grid's last point.
std::pair<double, double> range_under(const std::vector<double> &g, const std::vector<double> &p,
                                      double limit, bool open_above)
{
  std::size_t first = g.size(), last = 0;
  for (std::size_t i = 0; i < g.size(); ++i)
    if (p[i] <= limit) first = std::min(first, i), last = i;
  const auto cross = [&](std::size_t a, std::size_t b) {
    return g[a] + (g[b] - g[a]) * (limit - p[a]) / (p[b] - p[a]);
  };
  const double lo = first == 0 ? g[0] : cross(first - 1, first);
  const double hi = last + 1 == g.size() ? (open_above ? std::nan("") : g.back())
                                         : cross(last + 1, last);
  return {lo, hi};
}

// The fold less its cycle's first `harmonics` harmonics, fitted (weighted least squares) to the
// bins away from the pulse (from 0.45 of the period after the entry to `before` before it). Under a
// radial load R varies at BPFO (the balls' loads change as they pass the load line), and an outer
// pit's fold holds that modulation at a phase that turns Nb times as fast as the pit's angle
// (its second harmonic twice as fast): between two templates 15 deg apart the fundamental turns
// by 195 deg, so no template carries the record's; the pulse alone is compared. A bank with
// several angles removes the second harmonic too: mixed between two angles, the templates' would
// be neither's (held-out pits at 22.5 deg: reduced chi-square 14-39 with the fundamental alone,
// 1.6-2.7 with both, at 0.25-2.2 deg, 20 kHz), and keeps 0.15 of the period before the entry
// out of the fit: a pit 60 deg off the load has a first hump 0.065 of the period before the
// entry (the largest rise), which the second harmonic would otherwise follow.
std::vector<double> without_cycle(const std::vector<double> &y, const std::vector<double> &se,
                                  int harmonics, double before)
{
  const std::size_t n = y.size();
  const auto p = static_cast<std::size_t>(1 + 2 * harmonics);
  const double tau = 2 * kPi / static_cast<double>(n);
  const auto basis = [&](std::size_t j, std::size_t r) {
    if (r == 0) return 1.0;
    const double a = tau * static_cast<double>((r + 1) / 2) * static_cast<double>(j);
    return r % 2 ? std::cos(a) : std::sin(a);
  };
  std::vector<std::vector<double>> m(p, std::vector<double>(p + 1, 0.0));  // [A | b]
  for (std::size_t j = 0; j < n; ++j) {
    const double u = static_cast<double>(j) / static_cast<double>(n);
    if (u >= 0.25 - before && u < 0.7) continue;  // the entry lies at 0.25
    const double w = 1 / (se[j] * se[j]);
    for (std::size_t r = 0; r < p; ++r) {
      for (std::size_t c = 0; c < p; ++c) m[r][c] += w * basis(j, r) * basis(j, c);
      m[r][p] += w * basis(j, r) * y[j];
    }
  }
  for (std::size_t k = 0; k < p; ++k) {  // Gauss-Jordan, the matrix positive definite
    if (!(m[k][k] > 0)) return y;
    for (std::size_t r = 0; r < p; ++r) {
      if (r == k) continue;
      const double q = m[r][k] / m[k][k];
      for (std::size_t c = k; c <= p; ++c) m[r][c] -= q * m[k][c];
    }
  }
  std::vector<double> out(y);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t r = 1; r < p; ++r) out[j] -= m[r][p] / m[r][r] * basis(j, r);
  return out;
}

// The least of p over x: the vertex of the parabola through the smallest point and its two
// neighbours (kept between them), with its curvature; else the smallest point itself (an end of
// the grid, or no upward parabola), curvature 0.
struct Vertex {
  double x = 0, curvature = 0;  // p ~ p(x) + curvature (x' - x)^2 near x
};
Vertex vertex(const std::vector<double> &x, const std::vector<double> &p)
{
  const auto i = static_cast<std::size_t>(std::min_element(p.begin(), p.end()) - p.begin());
  if (i == 0 || i + 1 == p.size()) return {x[i], 0};
  const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
  const double d1 = (p[i] - p[i - 1]) / (x1 - x0), d2 = (p[i + 1] - p[i]) / (x2 - x1);
  const double a = (d2 - d1) / (x2 - x0);  // p = p[i] + b (x - x1) + a (x - x1)^2
  if (!(a > 0)) return {x1, 0};
  const double b = d1 + a * (x1 - x0);
  return {std::clamp(x1 - b / (2 * a), x0, x2), a};
}

}  // namespace

TemplateFit fit_templates(const FoldedPulse &rec, const TemplateBank &bank, double confidence)
{
  TemplateFit f;
  f.passes = rec.passes;
  if (!rec.valid) {
    f.note = "not determined: " + rec.note;
    return f;
  }
  if (!(confidence > 0 && confidence < 1))
    throw std::invalid_argument("template fit: confidence must lie in (0, 1)");
  std::vector<double> sizes, angles;
  bank_grid(bank, sizes, angles);
  if (std::fabs(bank.bin_s / rec.bin_s - 1) > 1e-6) {
    f.note = "not determined: the bank's fold bins (" + format_number(bank.bin_s, 6) +
             " s) are not the record's (" + format_number(rec.bin_s, 6) +
             " s): another sampling rate";
    return f;
  }
  // A template with bins no pass fell in (its run's period a near whole number of samples)
  // weighs nothing there; against a record with empty bins of its own, shifted so that each
  // one's filled bins meet the other's empty ones, it fits with no misfit at all (a 2.86 deg
  // inner pit read 3.7 deg on such a template). Its size is left out at every angle.
  std::vector<double> left_out;
  for (const PulseTemplate &t : bank.templates)
    if (bins_without_passes(t.se) > 0 &&
        std::find(left_out.begin(), left_out.end(), t.size_deg) == left_out.end())
      left_out.push_back(t.size_deg);
  std::sort(left_out.begin(), left_out.end());
  const auto is_left_out = [&](double size) {
    return std::binary_search(left_out.begin(), left_out.end(), size);
  };
  sizes.erase(std::remove_if(sizes.begin(), sizes.end(), is_left_out), sizes.end());
  std::string left_note;
  for (double v : left_out) left_note += (left_note.empty() ? "" : ", ") + format_number(v, 4);
  if (!left_out.empty())
    left_note = "; the bank's templates at " + left_note +
                " deg left out (bins no pass fell in: the run's period a near whole number of "
                "samples; a longer run fills them)";
  if (sizes.size() < 2) {
    f.note = "not determined: fewer than two of the bank's sizes have templates every bin of "
             "which passes fell in" + left_note;
    return f;
  }
  const int harmonics = angles.size() > 1 ? 2 : 1;
  const double before = angles.size() > 1 ? 0.15 : 0.05;
  std::vector<PulseTemplate> pulses;
  for (const PulseTemplate &t : bank.templates)
    if (!is_left_out(t.size_deg)) pulses.push_back(t);
  for (PulseTemplate &t : pulses) t.y = without_cycle(t.y, t.se, harmonics, before);
  FoldedPulse own = rec;
  own.y = without_cycle(rec.y, rec.se, harmonics, before);
  // the angle continuous: templates mixed between the bank's neighbouring angles
  const std::vector<double> bank_angles = angles;
  if (angles.size() > 1) pulses = between_angles(pulses, sizes, bank_angles, kAngleSteps, angles);
  const auto at = [&](std::size_t ia, std::size_t is) -> const PulseTemplate * {
    for (const PulseTemplate &t : pulses)
      if (t.size_deg == sizes[is] && t.angle_deg == angles[ia]) return &t;
    return nullptr;
  };
  std::size_t len = rec.y.size();
  for (const PulseTemplate &t : pulses) len = std::min(len, t.y.size());
  // the fit leaves out the period's last tenth: the templates' periods differ by a bin or two
  const auto n = static_cast<std::size_t>(0.9 * static_cast<double>(len));
  const int reach = 2 * kTemplateOversample;  // two samples either way
  // The misfit at each template (a real pulse of the scene), then interpolated in the size: a
  // mix of two templates whose exits lie a sample apart is two half steps, no pulse of the size
  // between, and the fit snapped to the bank's sizes (a 100 us pulse on templates at 90 and 130
  // us read 85 us, its interval not holding it).
  std::vector<double> prof_s(sizes.size(), 1e300), prof_a(angles.size(), 1e300);
  std::vector<double> shift_at(sizes.size(), 0.0);
  for (std::size_t ia = 0; ia < angles.size(); ++ia)
    for (std::size_t is = 0; is < sizes.size(); ++is) {
      const PulseTemplate &t = *at(ia, is);
      const Weighted m = weighted(t, n, kModelJitterS / rec.bin_s);
      const auto [c, shift] = best_shift(own, m, n, t.y.size() / 4, reach);
      if (c < prof_s[is]) prof_s[is] = c, shift_at[is] = shift;
      prof_a[ia] = std::min(prof_a[ia], c);
    }
  // sizes on a log scale (the bank's are a geometric series), angles as they are
  std::vector<double> ls(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) ls[i] = std::log(sizes[i]);
  // the place from the parabola through the best template and its neighbours; the threshold
  // from the best template's misfit (the parabola's own least value would dip below a flat
  // profile and cut its points out)
  const Vertex vs = vertex(ls, prof_s);
  f.size_deg = std::exp(vs.x);
  const double best = *std::min_element(prof_s.begin(), prof_s.end());
  const std::size_t ib =
      static_cast<std::size_t>(std::min_element(prof_s.begin(), prof_s.end()) - prof_s.begin());
  f.shift_s = shift_at[ib] * rec.bin_s;
  if (angles.size() > 1) f.angle_deg = vertex(angles, prof_a).x;
  // the record's empty bins weigh nothing: the degrees of freedom are its filled bins'
  const double filled = 1 - static_cast<double>(rec.empty) / static_cast<double>(rec.y.size());
  const double dof = filled * static_cast<double>(n) - 3 - (angles.size() > 1 ? 1 : 0);
  f.chi2_reduced = best / dof;
  // no template describes the record (another scene, or a size or angle beyond the bank): its
  // best misfit would still give a narrow interval around a wrong size
  if (f.chi2_reduced > kMaxReducedChi2) {
    f.note = "not determined: no template of the bank fits the record's pulse (reduced "
             "chi-square " + format_number(f.chi2_reduced, 3) + " > " +
             format_number(kMaxReducedChi2, 3) +
             " at the best, " + format_number(f.size_deg, 3) +
             " deg): another scene, or a size or place beyond the bank";
    f.size_deg = std::nan("");
    return f;
  }
  const double z = student_t_isf((1 - confidence) / 2, 1e9);
  // a misfit the pass scatter does not explain (the bank's own noise, the passes' correlation):
  // the errors scaled until the best fit's reduced chi-square is 1
  const double rise = z * z * std::max(1.0, f.chi2_reduced);
  auto [llo, lhi] = range_under(ls, prof_s, best + rise, true);
  // between the bank's sizes the parabola's own rise: the interval is the union of both
  if (vs.curvature > 0) {
    const double h = std::sqrt(rise / vs.curvature);
    llo = std::min(llo, vs.x - h);
    if (std::isfinite(lhi)) lhi = std::max(lhi, vs.x + h);
  }
  const double lo = std::exp(llo), hi = std::exp(lhi);
  // the bank's own error on held-out sizes, combined with the fit's half-widths
  const double me = z * bank.model_error * f.size_deg;
  f.size_lo_deg = std::max(0.0, f.size_deg - std::hypot(f.size_deg - std::min(lo, f.size_deg), me));
  if (llo <= ls.front()) f.size_lo_deg = 0;  // a smaller pit than the bank has fits as well
  f.size_hi_deg = std::isfinite(lhi)
                      ? f.size_deg + std::hypot(std::max(hi, f.size_deg) - f.size_deg, me)
                      : std::nan("");
  if (angles.size() > 1) {
    const auto [alo, ahi] = range_under(angles, prof_a, best + rise, false);
    // the profile is known at the mixed templates' angles only: widened by half their step
    double step = 0;
    for (std::size_t i = 1; i < angles.size(); ++i)
      step = std::max(step, angles[i] - angles[i - 1]);
    f.angle_lo_deg = std::max(0.0, std::min(alo, f.angle_deg) - step / 2);
    f.angle_hi_deg = std::max(ahi, f.angle_deg) + step / 2;
    // the bank's own error on pits between its angles, combined as the size's: the fold's shape
    // does not follow the angle smoothly between the bank's (a pit 26 deg off fitted 2-4 deg)
    f.angle_error_deg = bank.angle_error_deg;
    if (std::isfinite(bank.angle_error_deg)) {
      const double ae = z * bank.angle_error_deg;
      f.angle_lo_deg = std::max(0.0, f.angle_deg - std::hypot(f.angle_deg - f.angle_lo_deg, ae));
      f.angle_hi_deg = f.angle_deg + std::hypot(f.angle_hi_deg - f.angle_deg, ae);
    }
  }
  f.profile_size_deg = sizes;
  f.profile_chi2 = prof_s;
  const double flat = *std::max_element(prof_s.begin(), prof_s.end()) - best;
  f.valid = true;
  f.note = "pulse template fit: " + std::to_string(rec.passes) + " passes folded at 1/" +
           std::to_string(kTemplateOversample) + " sample, " +
           std::to_string(sizes.size() * bank_angles.size()) + " templates, reduced chi-square " +
           format_number(f.chi2_reduced, 3) + ", the profile rises by " +
           format_number(flat / rise, 3) + " times the interval's threshold over the bank's sizes" +
           left_note;
  return f;
}

FoldedPulse record_fold(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o)
{
  DefectLocation l;
  const RaceToSize r = race_to_size(found, o, "the pulse template", l);
  if (!r.race) {
    FoldedPulse p;
    p.note = l.method;
    return p;
  }
  return fold_pulse(s.x, s.rate, r.f, kTemplateOversample,
                    o.fine_fold_period ? FoldPeriod::fine : FoldPeriod::grid);
}

DefectLocation locate_by_template(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o)
{
  // the place (and the area's quantities) as the area method gives them: the inner pit's angle
  // from its passes through the load zone, the outer pit's from the pulses' phase; they do not
  // use the jump, so a unit one stands in where none is given
  DiagnoseOptions po = o;
  if (!(po.pulse_height > 0) && po.curve_size_deg.empty()) po.pulse_height = 1;
  DefectLocation l = locate_defect(s, found, po);
  l.valid = false;
  l.size_deg = l.size_lo_deg = l.size_hi_deg = l.arc_m = std::nan("");
  l.pulse_height = 0;
  l.height_source = "no pulse height: the model's pulse templates ({diagnose.model})";
  DefectLocation why;
  const RaceToSize r = race_to_size(found, o, "the pulse template", why);
  if (!r.race) {
    why.depth_note = l.depth_note;
    return why;
  }
  if (!o.template_bank) {
    set_method(l, r, "not determined: the template fit needs the model's bank "
                     "({diagnose.model})");
    return l;
  }
  const FoldedPulse p = fold_pulse(s.x, s.rate, r.f, kTemplateOversample,
                                   o.fine_fold_period ? FoldPeriod::fine : FoldPeriod::grid);
  const TemplateFit f = fit_templates(p, *o.template_bank);
  l = take_size(l, r, o.geometry, f);
  if (l.valid && std::isfinite(f.angle_deg)) {
    l.fit_angle_deg = f.angle_deg;
    l.fit_angle_lo_deg = f.angle_lo_deg;
    l.fit_angle_hi_deg = f.angle_hi_deg;
    pick_branch(l, f);
  }
  return l;
}

}  // namespace ohmdem::post
