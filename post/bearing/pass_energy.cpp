// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/pass_energy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bearing/diagnose.h"
#include "bearing/event_direction.h"
#include "bearing/load_zone_fit.h"
#include "bearing/race_sizing.h"
#include "core/constants.h"
#include "core/sampled_signal.h"
#include "dsp/butterworth.h"
#include "dsp/detect_laws.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {

std::size_t smoothing_samples(double rate)
{
  return static_cast<std::size_t>(std::max(1.0, std::round(1e-4 * rate)));
}

PassWindows pass_windows(const std::vector<double> &e, double rate, double f)
{
  PassWindows out;
  const double period = rate / f;  // samples per pass
  const auto w = static_cast<std::size_t>(std::floor(period / 6));
  out.half = w;
  if (w < 1 || e.size() < 4 * static_cast<std::size_t>(period)) return out;
  // the events are found on the squared record smoothed over 0.1 ms (one sample at 10 kHz), so
  // that one noisy sample does not place a window
  const std::size_t k = smoothing_samples(rate);
  std::vector<double> sm(e.size(), 0.0);
  double acc = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    acc += e[i];
    if (i >= k) acc -= e[i - k];
    sm[i - std::min(i, k / 2)] = acc;
  }
  auto strongest = [&](double at, double reach) {
    return strongest_in(sm, at, reach, w, sm.size() - w - 1);
  };
  auto energy = [&](std::size_t c) {
    double sum = 0;
    for (std::size_t i = c - w; i <= c + w; ++i) sum += e[i];
    return sum / rate;
  };
  const double end =
      static_cast<double>(e.size()) - period / 2 - period / 12 - static_cast<double>(w) - 2;
  // the first pass: the strongest event of the first period
  std::size_t c = strongest(static_cast<double>(w) + period / 2, period / 2);
  // the last pass whose event stood out (twice its background's energy and within 20 dB of
  // the strongest pass so far: a record's quantization alone gives empty windows energy
  // ratios of any size), and the passes since: a pass without one (a defect outside the load
  // zone) is searched for where the period puts it from there, not from its window's largest
  // sample, which lies at its edge in the last event's tail (the search would drift away from
  // the events a quarter period a pass)
  double anchor = static_cast<double>(c), since = 0, strongest_pass = 0;
  while (static_cast<double>(c) < end) {
    // the background half a period later, not searched: a search there would centre it on
    // the peaks of any steady tone and subtract more than the tone's mean energy
    const auto b = static_cast<std::size_t>(std::lround(static_cast<double>(c) + period / 2));
    const double ec = energy(c), eb = energy(b);
    out.energy.push_back(ec - eb);
    out.at.push_back(c);
    out.background.push_back(b);
    strongest_pass = std::max(strongest_pass, ec - eb);
    if (ec > 2 * eb && ec - eb >= 1e-2 * strongest_pass) {
      anchor = static_cast<double>(c);
      since = 0;
    }
    ++since;
    const double next = anchor + since * period;
    if (next + period / 4 + static_cast<double>(w) + 1 >= static_cast<double>(e.size())) break;
    c = strongest(next, period / 4);
  }
  return out;
}

void check_pass_settings(const PassEnergySettings &s, double rate, double f)
{
  if (s.groups < 3 || !(s.confidence > 0 && s.confidence < 1) || !(rate > 0 && f > 0))
    throw std::invalid_argument(
        "pass energy: settings out of range (at least 3 groups, confidence in (0, 1), rate "
        "and defect frequency > 0)");
}

PassEnergies pass_energies(const std::vector<double> &x, double rate, double f,
                           const PassEnergySettings &s)
{
  check_pass_settings(s, rate, f);
  PassEnergies out;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> e(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) e[i] = (x[i] - mean) * (x[i] - mean);
  const PassWindows pw = pass_windows(e, rate, f);
  out.energy = pw.energy;
  out.at.assign(pw.at.begin(), pw.at.end());
  const std::size_t n = out.energy.size();
  if (n < s.groups) return out;
  out.mean = 0;
  for (double v : out.energy) out.mean += v;
  out.mean /= static_cast<double>(n);
  out.group_mean.assign(s.groups, 0.0);
  std::vector<std::size_t> count(s.groups, 0);
  for (std::size_t j = 0; j < n; ++j) {
    out.group_mean[j * s.groups / n] += out.energy[j];
    ++count[j * s.groups / n];
  }
  for (std::size_t g = 0; g < s.groups; ++g) out.group_mean[g] /= static_cast<double>(count[g]);
  return out;
}

double size_on_energy_curve(const std::vector<double> &size_deg, const std::vector<double> &energy,
                            double e)
{
  const std::size_t n = std::min(size_deg.size(), energy.size());
  if (n < 2 || !(e > 0) || e > energy[n - 1]) return std::nan("");
  std::size_t k = 1;
  while (k + 1 < n && e > energy[k]) ++k;
  // the energy grows like a power of the size (about 4 for small pits, 1-2 for large ones):
  // a power law between the points, where linear interpolation would read sizes high
  const double p = std::log(energy[k] / energy[k - 1]) / std::log(size_deg[k] / size_deg[k - 1]);
  return size_deg[k - 1] * std::pow(e / energy[k - 1], 1 / p);
}

PassEnergySize size_from_pass_energy(const std::vector<double> &x, double rate, double f,
                                     const std::string &defect, const PassEnergySettings &s)
{
  PassEnergySize r;
  if (defect != "inner" && defect != "outer") {
    r.note = "not determined: the pass energy is sized for race defects (inner, outer)";
    return r;
  }
  if (!(rate > 0 && f > 0 && f < rate / 8)) {
    r.note = "not determined: the defect frequency must lie below an eighth of the rate";
    return r;
  }
  const PassEnergies pe = pass_energies(x, rate, f, s);
  r.passes = pe.energy.size();
  if (pe.group_mean.empty()) {
    r.note = "not determined: " + std::to_string(r.passes) + " defect passes in the record, " +
             "fewer than the " + std::to_string(s.groups) + " groups of the interval";
    return r;
  }
  r.energy = pe.mean;
  const auto g = static_cast<double>(pe.group_mean.size());
  double var = 0;
  for (double v : pe.group_mean) var += (v - pe.mean) * (v - pe.mean);
  var /= g - 1;
  const double t = student_t_isf((1 - s.confidence) / 2, g - 1);
  const double z = student_t_isf((1 - s.confidence) / 2, 1e9);
  // the groups' scatter and the curve's own error, both relative to the energy's level
  const double half = std::sqrt(t * t * var / g + std::pow(z * s.curve_rel_error * pe.mean, 2));
  r.energy_lo = pe.mean - half;
  r.energy_hi = pe.mean + half;
  const std::string how = "pass energy " + format_number(pe.mean, 4) + " V^2 s over " +
                          std::to_string(r.passes) + " passes";
  if (s.curve_size_deg.size() < 2) {
    r.note = "not determined: no model curve (" + how + ")";
    return r;
  }
  if (!(pe.mean > 0)) {
    r.note = "not determined: the passes' energy does not stand above the background (" + how + ")";
    return r;
  }
  r.size_deg = size_on_energy_curve(s.curve_size_deg, s.curve_energy, pe.mean);
  if (!std::isfinite(r.size_deg)) {
    r.note = "not determined: the pass energy lies beyond the model's curve (" + how + ")";
    return r;
  }
  r.size_lo_deg =
      r.energy_lo > 0 ? size_on_energy_curve(s.curve_size_deg, s.curve_energy, r.energy_lo) : 0.0;
  r.size_hi_deg = size_on_energy_curve(s.curve_size_deg, s.curve_energy, r.energy_hi);
  r.valid = true;
  r.note = "pass energy on the model's curve: " + how;
  return r;
}

DefectLocation locate_by_pass_energy(const Signal &s, const Diagnosis &found,
                                    const DiagnoseOptions &o)
{
  DefectLocation l;
  l.height_source = "no pulse height: the model's curve of the pass energy";
  l.depth_note = "not determined: the pass energy is read as the pit's length along the raceway";
  const RaceToSize r = race_to_size(found, o, "the pass energy", l);
  if (!r.race) return l;
  PassEnergySettings ps;
  ps.curve_size_deg = o.curve_size_deg;
  ps.curve_energy = o.curve_rel_area_s;
  ps.curve_rel_error = o.curve_rel_error;
  const PassEnergySize e = size_from_pass_energy(s.x, s.rate, r.f, r.defect, ps);
  l.pass_energy = e.energy;
  l = take_size(l, r, o.geometry, e);
  place_inner_by_pass_energy(s, r, o, l);
  place_outer_by_event_direction(s, r, o, l);
  return l;
}

namespace {

// The anti-alias filter's delay of the record's events (s): its group delay weighted by the
// record's power spectrum, how far the filter moves the energy centroid of a signal with this
// spectrum; the events of an accelerometer record lie near the cut-off, where the group delay
// exceeds the one at 0 Hz (by 42 us for 3 kHz behind the 4 kHz filter of a 10 kHz record). The
// delay at 0 Hz without the filter (or with no power).
double event_delay_s(const Signal &s, const DiagnoseOptions &o)
{
  if (!o.record_filter || s.x.size() < 2) return o.record_delay_s;
  SpectrumOptions so;
  so.scaling = Scaling::Power;
  const Spectrum p = spectrum(s.x, s.rate, so);
  double power = 0, weighted = 0;
  for (std::size_t k = 1; k < p.bins(); ++k) {
    power += p.value[k];
    weighted +=
        p.value[k] * sos_group_delay_s(o.record_filter->sos, p.frequency(k), o.record_filter->fs);
  }
  return power > 0 ? weighted / power : o.record_delay_s;
}

}  // namespace

void place_inner_by_pass_energy(const Signal &s, const RaceToSize &r, const DiagnoseOptions &o,
                                DefectLocation &l)
{
  if (r.defect != "inner") return;
  if (o.load != "radial") {
    l.position_note = o.load.empty()
                          ? "not determined: needs the load mode ({diagnose.load}, or run.json)"
                          : "not determined: under a balanced load every pass looks the same";
    return;
  }
  if (!o.shaft_angle || o.shaft_angle->empty()) {
    l.position_note = "not determined: the record has no shaft angle (angle or tachometer column)";
    return;
  }
  const PassEnergies pe = pass_energies(s.x, s.rate, r.f, PassEnergySettings{});
  const std::size_t n = pe.energy.size();
  if (n < 8) {
    l.position_note = "not determined: " + std::to_string(n) + " defect passes, fewer than 8";
    return;
  }
  // each pass's time: its strongest event's (the ball it meets, wherever the cage holds it),
  // less the anti-alias filter's delay of the events
  const double delay = event_delay_s(s, o);
  std::vector<double> t(n);
  for (std::size_t j = 0; j < n; ++j) t[j] = s.t0 + pe.at[j] / s.rate - delay;
  const ZoneEstimate z =
      zone_estimate(shaft_angles_at(t, s.rate, s.t0, o.shaft_angle, o.fr), pe.energy);
  if (!(z.c > 0)) {
    l.position_note = "not determined: the passes' energy does not follow the load zone";
    return;
  }
  // and the shaft's turn over the smoothing window: where in it the event lies is not resolved
  // (the ring's response and the exit's place in the pit move the energy's peak by about that
  // much)
  const double smear_deg = 360 * o.fr * static_cast<double>(smoothing_samples(s.rate)) / s.rate;
  const double half = student_t_isf(0.025, static_cast<double>(n - 1)) * z.phi_sd + smear_deg;
  l.position_deg = wrap_deg(kLoadDirectionDeg - z.phi_deg);
  l.position_lo_deg = wrap_deg(l.position_deg - half);
  l.position_hi_deg = wrap_deg(l.position_deg + half);
  l.position_reference = "shaft zero";
  l.position_note.clear();
}

}  // namespace ohmdem::post
