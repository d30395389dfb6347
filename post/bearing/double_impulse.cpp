// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/double_impulse.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bearing/diagnose.h"
#include "bearing/event_direction.h"
#include "bearing/pass_energy.h"
#include "bearing/race_sizing.h"
#include "core/constants.h"
#include "core/sampled_signal.h"
#include "dsp/detect_laws.h"
#include "dsp/envelope.h"

namespace ohmdem::post {

std::vector<double> ar_residual(const std::vector<double> &x, int p)
{
  const std::size_t n = x.size();
  if (p <= 0 || n <= static_cast<std::size_t>(2 * p)) return x;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(n);
  const auto order = static_cast<std::size_t>(p);
  std::vector<double> xm(n);
  for (std::size_t i = 0; i < n; ++i) xm[i] = x[i] - mean;
  // r[k] = sum over i of xm[i] xm[i - k], i ascending: the lags side by side, not one after
  // the other (the same sums, in the same order, with independent additions)
  std::vector<double> r(order + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double *back = xm.data() + i;
    const std::size_t lags = std::min(order, i);
    for (std::size_t k = 0; k <= lags; ++k) r[k] += back[0] * *(back - k);
  }
  if (!(r[0] > 0)) return std::vector<double>(n, 0.0);
  // Levinson-Durbin: a[0] = 1, prediction error e; a tiny diagonal load keeps it stable on
  // records that are nearly a sum of a few sines
  r[0] *= 1 + 1e-9;
  std::vector<double> a(static_cast<std::size_t>(p) + 1, 0.0), prev;
  a[0] = 1;
  double e = r[0];
  for (int m = 1; m <= p; ++m) {
    double acc = r[m];
    for (int j = 1; j < m; ++j) acc += a[j] * r[m - j];
    const double k = -acc / e;
    prev = a;
    for (int j = 1; j < m; ++j) a[j] = prev[j] + k * prev[m - j];
    a[m] = k;
    e *= 1 - k * k;
    if (!(e > 0)) break;
  }
  // out[i] = sum over j ascending of a[j] xm[i - j]; blocks of samples take one coefficient at
  // a time (the same sums, in the same order, a loop that vectorises)
  std::vector<double> out(n, 0.0);
  constexpr std::size_t kBlock = 1024;
  for (std::size_t i0 = order; i0 < n; i0 += kBlock) {
    const std::size_t i1 = std::min(n, i0 + kBlock);
    for (std::size_t j = 0; j <= order; ++j) {
      const double aj = a[j];
      const double *in = xm.data() + i0 - j;
      double *o = out.data() + i0;
      for (std::size_t i = 0; i < i1 - i0; ++i) o[i] += aj * in[i];
    }
  }
  return out;
}

namespace {

// The settings are the library's own (no command sets them): a bad one is a programming
// error, not the user's.
void check(const DoubleImpulseSettings &s)
{
  if (s.ar_order > 1000 || s.groups < 3 || !(s.confidence > 0 && s.confidence < 1) ||
      !(s.min_delay_samples >= 1) || !(s.band_lo >= 0) || (s.band_hi > 0 && s.band_hi <= s.band_lo))
    throw std::invalid_argument(
        "double impulse: settings out of range (AR order at most 1000, at least 3 groups, "
        "confidence in (0, 1), at least 1 sample of delay, 0 <= band low < band high)");
}

// The secondary peak of an averaged autocorrelation: the largest value after the main lobe's
// first minimum, refined by a parabola through its neighbours. lag < 0 when there is none.
struct Peak {
  double lag = -1, contrast = 0;
  std::size_t dip = 0;
};
Peak secondary_peak(const std::vector<double> &acf)
{
  Peak p;
  std::size_t m = 1;
  while (m + 1 < acf.size() && acf[m + 1] < acf[m]) ++m;
  p.dip = m;
  std::size_t best = 0;
  for (std::size_t k = m + 1; k + 1 < acf.size(); ++k)
    if (acf[k] >= acf[k - 1] && acf[k] >= acf[k + 1] && (best == 0 || acf[k] > acf[best])) best = k;
  if (best == 0) return p;
  p.contrast = acf[best] - acf[m];
  const double a = acf[best - 1], b = acf[best], c = acf[best + 1];
  const double den = a - 2 * b + c;
  p.lag = static_cast<double>(best) + (den < 0 ? 0.5 * (a - c) / den : 0.0);
  return p;
}

// The local maximum of acf nearest to `lag` within +-w samples, refined by a parabola; NaN if
// the window holds none.
double peak_near(const std::vector<double> &acf, double lag, double w)
{
  const auto lo = static_cast<std::size_t>(std::max(1.0, std::floor(lag - w)));
  const auto hi = std::min(acf.size() - 2, static_cast<std::size_t>(std::ceil(lag + w)));
  std::size_t best = 0;
  for (std::size_t k = lo; k <= hi; ++k)
    if (acf[k] >= acf[k - 1] && acf[k] >= acf[k + 1] && (best == 0 || acf[k] > acf[best])) best = k;
  if (best == 0) return std::nan("");
  const double a = acf[best - 1], b = acf[best], c = acf[best + 1];
  const double den = a - 2 * b + c;
  return static_cast<double>(best) + (den < 0 ? 0.5 * (a - c) / den : 0.0);
}

}  // namespace

PassAutocorrelation pass_autocorrelation(const std::vector<double> &x, double rate, double f,
                                         const DoubleImpulseSettings &s)
{
  check(s);
  PassAutocorrelation out;
  const double period = rate / f;  // samples per pass
  // segments of half a period (lags up to a quarter): a pass's entry and exit lie within a
  // quarter period of its strongest event, and a segment half a period away holds no event
  const auto half = static_cast<std::size_t>(std::floor(period / 4));
  if (half < 3 || x.size() < 4 * static_cast<std::size_t>(period)) return out;
  const int p = s.ar_order == 0 ? std::min(32, static_cast<int>(period / 4)) : s.ar_order;
  std::vector<double> e = envelope(ar_residual(x, p), rate, Band{s.band_lo, s.band_hi});
  for (double &v : e) v *= v;
  // The passes: each segment is centred on the strongest event within a quarter period of
  // where the pass is expected (the last one's plus a period), so that a slipping defect
  // frequency does not smear the events; its autocorrelation then holds entry and exit.
  const double skip = std::max(p, 0) + static_cast<double>(half) + period / 4;  // AR start-up
  // The same from segments half a period away (between the passes, centred the same way on
  // their strongest value): the background's own autocorrelation, whose ripple a peak must
  // stand above.
  std::vector<std::vector<double>> acfs, bgs;
  const auto len = 2 * half;
  std::vector<double> seg(len);
  auto strongest = [&](double at, double reach) {
    return strongest_in(e, at, reach, half, e.size() - 1);
  };
  auto acf_at = [&](std::size_t mx) {
    double mean = 0;
    for (std::size_t i = 0; i < len; ++i) mean += (seg[i] = e[mx - half + i]);
    mean /= static_cast<double>(len);
    for (double &v : seg) v -= mean;
    // r[m] = sum over i ascending of seg[i] seg[i + m]: the lags side by side (the same sums
    // in the same order, a loop that vectorises)
    std::vector<double> r(half + 1, 0.0);
    for (std::size_t i = 0; i < len; ++i) {
      const double si = seg[i];
      const std::size_t lags = std::min(half, len - 1 - i);
      for (std::size_t m = 0; m <= lags; ++m) r[m] += si * seg[i + m];
    }
    return r;
  };
  const auto end = static_cast<double>(e.size()) - period - static_cast<double>(half) - 1;
  for (double expect = skip; expect < end;) {
    const std::size_t mx = strongest(expect, period / 4);
    acfs.push_back(acf_at(mx));
    bgs.push_back(acf_at(strongest(static_cast<double>(mx) + period / 2, period / 8)));
    expect = static_cast<double>(mx) + period;
  }
  out.passes = acfs.size();
  if (out.passes < s.groups) return out;
  auto normalised = [](std::vector<double> v) {
    const double z = v[0] > 0 ? v[0] : 1;
    for (double &w : v) w /= z;
    return v;
  };
  auto average = [&](const std::vector<std::vector<double>> &v, std::vector<double> &all,
                     std::vector<std::vector<double>> &groups) {
    all.assign(half + 1, 0.0);
    groups.assign(s.groups, std::vector<double>(half + 1, 0.0));
    for (std::size_t k = 0; k < v.size(); ++k) {
      auto &g = groups[k * s.groups / v.size()];
      for (std::size_t m = 0; m <= half; ++m) {
        all[m] += v[k][m];
        g[m] += v[k][m];
      }
    }
    all = normalised(all);
    for (auto &g : groups) g = normalised(g);
  };
  average(acfs, out.acf, out.group_acf);
  average(bgs, out.background_acf, out.group_background_acf);
  return out;
}

DoubleImpulseSize size_from_double_impulse(const std::vector<double> &x, double rate, double f,
                                           const std::string &defect, int nb,
                                           const DoubleImpulseSettings &s)
{
  DoubleImpulseSize r;
  if (defect != "inner" && defect != "outer") {
    r.note = "not determined: the double-impulse size is for race defects (inner, outer)";
    return r;
  }
  if (!(rate > 0 && f > 0 && f < rate / 8 && nb > 0)) {
    r.note = "not determined: the defect frequency must lie below an eighth of the rate";
    return r;
  }
  const PassAutocorrelation pa = pass_autocorrelation(x, rate, f, s);
  r.passes = pa.passes;
  if (pa.acf.empty()) {
    r.note = "not determined: " + std::to_string(pa.passes) + " defect passes in the record, " +
             "fewer than the " + std::to_string(s.groups) + " groups of the interval";
    return r;
  }
  Peak pk = secondary_peak(pa.acf);
  r.contrast = pk.contrast;
  // delay -> size: (angular speed of the ball relative to the ring) x delay = 2 pi f tau / Nb
  const double deg_per_s = 360.0 * f / nb;
  if (pk.lag < 0 || pk.contrast < s.min_contrast) {
    r.note = "not determined: no entry-exit pair in the passes' autocorrelation (secondary peak " +
             std::string(pk.lag < 0 ? "absent" : "below the contrast threshold") +
             "); the events are merged, or the record shows one event per pass";
    return r;
  }
  // the peak must stand above the pass groups' scatter of the same contrast (3 standard
  // errors): noise alone gives a secondary maximum somewhere
  {
    const auto k = static_cast<std::size_t>(std::lround(pk.lag));
    double m = 0, v = 0;
    const std::size_t ng = pa.group_acf.size();
    std::vector<double> c(ng);
    for (std::size_t j = 0; j < ng; ++j) {
      const auto &g = pa.group_acf[j], &b = pa.group_background_acf[j];
      c[j] = g[k] - g[pk.dip] - (b[k] - b[pk.dip]);
      m += c[j];
    }
    m /= static_cast<double>(ng);
    for (double cj : c) v += (cj - m) * (cj - m);
    const double se = std::sqrt(v / static_cast<double>(ng - 1) / static_cast<double>(ng));
    r.contrast = m;
    if (!(m > 3 * se && m >= s.min_contrast)) {
      r.note = "not determined: the secondary peak of the passes' autocorrelation stands " +
               format_number(m, 3) + " above the background's (between the passes), not " +
               "3 standard errors of the pass groups (" + format_number(se, 3) + ") and " +
               format_number(s.min_contrast, 3) + ": no entry-exit pair stands out";
      return r;
    }
  }
  if (static_cast<double>(pk.dip) >= pk.lag) pk.lag = static_cast<double>(pk.dip) + 1;
  r.delay_s = pk.lag / rate;
  if (pk.lag < s.min_delay_samples) {
    r.note = "not determined: the entry-exit delay is under " +
             format_number(s.min_delay_samples, 3) + " samples at this rate";
    return r;
  }
  std::vector<double> lags;
  for (const auto &g : pa.group_acf) {
    const double l = peak_near(g, pk.lag, std::max(2.0, 0.3 * pk.lag));
    if (std::isfinite(l)) lags.push_back(l);
  }
  if (lags.size() < 3) {
    r.note = "not determined: the entry-exit peak is not found in " +
             std::to_string(pa.group_acf.size() - lags.size()) + " of " +
             std::to_string(pa.group_acf.size()) + " pass groups";
    return r;
  }
  double mean = 0, var = 0;
  for (double l : lags) mean += l;
  mean /= static_cast<double>(lags.size());
  for (double l : lags) var += (l - mean) * (l - mean);
  var /= static_cast<double>(lags.size() - 1);
  const double t = student_t_isf((1 - s.confidence) / 2, static_cast<double>(lags.size() - 1));
  // the groups' scatter with half a sample for the parabola's bias on a sampled peak
  const double half_width = std::sqrt(t * t * var / static_cast<double>(lags.size()) + 0.25) / rate;
  r.delay_lo_s = std::max(0.0, r.delay_s - half_width);
  r.delay_hi_s = r.delay_s + half_width;
  r.size_deg = deg_per_s * r.delay_s;
  r.size_lo_deg = deg_per_s * r.delay_lo_s;
  r.size_hi_deg = deg_per_s * r.delay_hi_s;
  r.valid = true;
  r.note = "double impulse: entry-exit delay " + format_number(r.delay_s * 1e6, 4) + " us over " +
           std::to_string(r.passes) + " passes";
  return r;
}

DefectLocation locate_by_double_impulse(const Signal &s, const Diagnosis &found,
                                       const DiagnoseOptions &o)
{
  DefectLocation l;
  l.height_source = "no pulse height: the interval from the pass groups' delays";
  l.depth_note =
      "not determined: the entry and exit events give the pit's length along the raceway only";
  const RaceToSize r = race_to_size(found, o, "the double impulse", l);
  if (!r.race) return l;
  const BearingGeometry &g = o.geometry;
  if (!(g.db > 0 && g.dp > 0) || g.nb < 2) {
    l.method = "needs the ball count and the ball and pitch diameters";
    return l;
  }
  const DoubleImpulseSize e = size_from_double_impulse(s.x, s.rate, r.f, r.defect, g.nb, {});
  l = take_size(l, r, g, e);
  place_inner_by_pass_energy(s, r, o, l);
  place_outer_by_event_direction(s, r, o, l);
  return l;
}

}  // namespace ohmdem::post
