// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/defect_size.h"

#include <algorithm>
#include <cmath>

#include "bearing/outer_position.h"
#include "bearing/pulse_area.h"
#include "bearing/pulse_edges.h"
#include "core/constants.h"
#include "core/sampled_signal.h"
#include "dsp/detect_laws.h"
#include "dsp/pulses.h"

namespace ohmdem::post {

double defect_angle(const std::string &defect, double f, double tau, int nb)
{
  if (defect == "inner" || defect == "outer") return 2 * kPi * f * tau / nb;
  if (defect == "ball") return kPi * f * tau;
  return 0;
}

SizeEstimate estimate_size(const Signal &s, const Diagnosis &d, const BearingGeometry &g)
{
  SizeEstimate e;
  if (d.defect != "inner" && d.defect != "outer" && d.defect != "ball") {
    e.method = "not applicable";
    return e;
  }
  if (!(g.db > 0 && g.dp > 0)) {  // factors only: no race radius to turn a width into a size
    e.method = "needs the ball and pitch diameters (the bearing gives factors only)";
    return e;
  }
  const double f = d.frequency_hz;
  const PulseTrain p = detect_pulses(s.x, s.rate);
  // pulses repeat at the matched frequency (at twice a matched BSF for a ball)
  const double per_pulse = d.defect == "ball" && d.label == "BSF" ? 2 * f : f;
  const bool periodic =
      p.median_spacing_s > 0 && std::fabs(p.median_spacing_s * per_pulse - 1) < 0.1;
  if (p.clean && periodic) {
    e.method = "pulses";
    e.pulse_width_s = p.median_width_s;
    e.pulses = p.counted;
  } else {
    const AveragedPulse a =
        synchronous_pulse(s.x, s.rate, refine_repetition(s.x, s.rate, per_pulse));
    if (!a.valid) {
      e.method = "no clean pulse train (vibration record or too noisy)";
      return e;
    }
    e.method = "synchronous average";
    e.pulse_width_s = a.width_s;
    e.pulses = a.cycles;
  }
  const double angle = defect_angle(d.defect, per_pulse, e.pulse_width_s, g.nb);
  const double r = d.defect == "ball" ? g.db / 2
                   : d.defect == "inner"
                       ? (g.dp - g.db * std::cos(g.contact_angle_deg * kPi / 180)) / 2
                       : (g.dp + g.db * std::cos(g.contact_angle_deg * kPi / 180)) / 2;
  e.size_deg = angle * 180 / kPi;
  e.arc_m = angle * r;
  e.valid = true;
  return e;
}

}  // namespace ohmdem::post

namespace ohmdem::post {

namespace {

double race_radius(const std::string &defect, const BearingGeometry &g)
{
  const double c = g.db * std::cos(g.contact_angle_deg * kPi / 180);
  return defect == "inner" ? (g.dp - c) / 2 : (g.dp + c) / 2;
}

void size_from_area(DefectLocation &l, const PulseAreaSize &a, const Signal &s, const Diagnosis &d,
                    const Diagnosis &found, const DiagnoseOptions &o, bool curve);
void place(DefectLocation &l, const PulseAreaSize &a, const Diagnosis &d, bool radial,
           const DiagnoseOptions &o);
void place_outer(DefectLocation &l, const Signal &s, const Diagnosis &d, int nb);

}  // namespace

DefectLocation locate_defect(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o)
{
  Diagnosis d = found;
  if (!o.assume_defect.empty() && o.assume_defect != found.defect) {
    d.defect = o.assume_defect;
    d.frequency_hz = o.assume_defect == "inner" ? found.kinematics.bpfi : found.kinematics.bpfo;
  }
  DefectLocation l;
  const BearingGeometry &g = o.geometry;
  l.depth_note =
      "not determined: the pulses give the defect's width and the jump of the level; the depth "
      "shows only while the ball reaches the pit floor";
  if (d.defect == "ball") {
    l.method = "not determined by the pulse area (a ball defect)";
    l.position_note = "not determined: the defective ball cannot be told from the others";
    return l;
  }
  if (d.defect != "inner" && d.defect != "outer") {
    l.method = "not applicable";
    return l;
  }
  l.position_note = "not determined";
  if (!(g.db > 0 && g.dp > 0) || g.nb < 2) {
    l.method = "needs the ball count and the ball and pitch diameters";
    return l;
  }
  const bool radial = o.load == "radial";
  const bool curve = !o.curve_size_deg.empty();
  if (curve) {
    l.height_source = "the model's curve ({diagnose.size_curve})";
  } else if (o.pulse_height > 0) {
    l.pulse_height = o.pulse_height;
    l.height_source = "{diagnose.pulse_height}";
  } else if (o.load == "force" || o.load == "fixed") {
    // every ball carries the same load: one path of Nb lost raises R by 1 / (Nb - 1)
    l.pulse_height = 1.0 / (g.nb - 1);
    l.height_source = "theory: Nb equal parallel paths, one lost: 1/(Nb-1)";
  } else {
    l.method =
        radial ? "not determined: under a radial load the jump depends on the ball's place in the "
                 "load zone: give the model's data of the scene ({diagnose.model}: a bank or the "
                 "area's curve) or {diagnose.pulse_height} (the jump at the zone's centre, from a "
                 "simulation of the scene)"
               : "needs the load mode ({diagnose.load}, or run.json) or {diagnose.pulse_height}";
    return l;
  }
  PulseAreaSettings ps;
  ps.rel_height = l.pulse_height;
  ps.load_zone = radial;
  ps.fr = o.fr;
  ps.shaft_angle = o.shaft_angle;
  ps.delay = o.record_delay_s;
  ps.curve_size_deg = o.curve_size_deg;
  ps.curve_rel_area_s = o.curve_rel_area_s;
  ps.curve_rel_error = o.curve_rel_error;
  const PulseAreaSize a = size_from_pulse_area(s.x, s.rate, s.t0, d.frequency_hz, d.defect, ps);
  l.method = a.note;
  if (d.defect != found.defect)
    l.method = "assumed " + d.defect + " defect ({diagnose.assume_defect}); " + l.method;
  l.passes = a.passes;
  l.window_rel_area_s = a.window_rel_area_s;
  // Where the record's entry-to-exit width lies on the model's width curve (which starts where
  // the chain resolves the pulse), the size comes from the width: the area stops growing past
  // ~1 deg when the ring is free to move (doc/methods/size_pulse_area.md).
  CurveReading w;
  if (a.passes > 0) {
    const PulseEdges pe = pulse_edge_width(s.x, s.rate, d.frequency_hz);
    if (pe.valid) {
      l.edge_width_s = pe.width_s;
      if (!o.width_curve_size_deg.empty()) {
        const double tq = student_t_isf(0.025, static_cast<double>(pe.blocks) - 1);
        const double z = student_t_isf(0.025, 1e9) * o.width_rel_error * pe.width_s;
        w = read_on_curve(o.width_curve_size_deg, o.width_curve_s, pe.width_s,
                          std::hypot(tq * pe.se_s, z));
        // resolved: the crossing the width gives lasts kResolvedSamples samples or more (the
        // area is the better statistic below that)
        constexpr double kResolvedSamples = 2;
        const double tau = w.size * kPi / 180 * g.nb / (2 * kPi * d.frequency_hz);
        if (!(tau * s.rate >= kResolvedSamples)) w = CurveReading();
        if (std::isfinite(w.size))
          l.method = "pulse edges: entry-to-exit width " + format_number(pe.width_s * 1e6, 4) +
                     " us on the model's width curve, " + std::to_string(pe.blocks) + " blocks; " +
                     l.method;
      }
    }
  }
  // the phase places an outer pit, the load zone an inner one, whether or not its size is read
  if (d.defect == "outer" && radial) place_outer(l, s, d, g.nb);
  place(l, a, d, radial, o);
  if (!a.valid && !std::isfinite(w.size)) return l;
  if (std::isfinite(w.size)) {
    l.valid = true;
    l.size_deg = w.size;
    l.size_lo_deg = w.lo;
    l.size_hi_deg = w.hi;
    l.arc_m = w.size * kPi / 180 * race_radius(d.defect, g);
    l.height_source = "the model's width curve ({diagnose.width_curve})";
  } else {
    size_from_area(l, a, s, d, found, o, curve);
  }
  return l;
}

namespace {

void size_from_area(DefectLocation &l, const PulseAreaSize &a, const Signal &s, const Diagnosis &d,
                    const Diagnosis &found, const DiagnoseOptions &o, bool curve)
{
  const BearingGeometry &g = o.geometry;
  const double to_deg = 180 / kPi;
  const auto angle = [&](double tau) { return defect_angle(d.defect, d.frequency_hz, tau, g.nb); };
  // Without the model's curve the size rests on the theory's flat jump: the pulse is h level
  // high for the whole crossing. Where the record resolves the pulse (kResolved samples or more)
  // its width checks that: a pit the ball partly drops into, or a ring that rings after the
  // exit (the deck's default 5 um pits), gives an area that is not h times the width, and the
  // theory's size would be confidently wrong.
  constexpr double kResolved = 10, kFlatTolerance = 0.25;
  if (!curve && d.defect == found.defect && found.size.valid &&
      found.size.pulse_width_s * s.rate >= kResolved &&
      std::fabs(a.tau_s / found.size.pulse_width_s - 1) > kFlatTolerance) {
    l.method =
        "not determined: the pulses are not the flat jump the theory assumes (their area "
        "gives " +
        format_number(angle(a.tau_s) * to_deg, 3) + " deg, their width " +
        format_number(found.size.size_deg, 3) +
        " deg: the ball drops into the pit or the ring rings after the exit); give the "
        "model's curve ({diagnose.size_curve}, studies/sizing.py)";
    return;
  }
  l.valid = true;
  l.size_deg = angle(a.tau_s) * to_deg;
  l.size_lo_deg = angle(a.tau_lo_s) * to_deg;
  if (std::isfinite(a.tau_hi_s)) l.size_hi_deg = angle(a.tau_hi_s) * to_deg;
  l.arc_m = angle(a.tau_s) * race_radius(d.defect, g);
  if (curve) {  // the size read off the model's curve
    l.size_deg = a.size_deg;
    l.size_lo_deg = a.size_lo_deg;
    l.size_hi_deg = a.size_hi_deg;
    l.arc_m = a.size_deg * kPi / 180 * race_radius(d.defect, g);
  }
}

// An outer pit's angle from the load direction, modulo the ball spacing (outer_position.h).
void place_outer(DefectLocation &l, const Signal &s, const Diagnosis &d, int nb)
{
  const double f = refine_repetition(s.x, s.rate, d.frequency_hz);
  // the crossing bounds the pulse's centroid: the entry-to-exit width, else the pulse width
  const double crossing = std::isfinite(l.edge_width_s) ? l.edge_width_s
                          : d.size.valid                ? d.size.pulse_width_s
                                                        : std::nan("");
  const OuterPosition p = outer_position(s.x, s.rate, f, nb, crossing);
  if (!p.valid) {
    l.position_note = "not determined: " + p.note;
    return;
  }
  l.position_deg = p.angle_deg;
  l.position_lo_deg = p.angle_deg - p.half_width_deg;
  l.position_hi_deg = p.angle_deg + p.half_width_deg;
  l.position_modulo_deg = p.spacing_deg;
  l.position_reference = "load direction";
  l.position_note = "modulo the ball spacing " + format_number(p.spacing_deg, 4) +
                    " deg (the pulses' phase after the ball-pass modulation's maximum, " +
                    std::to_string(p.blocks) +
                    " blocks; the branch is not determined), positive in the balls' direction "
                    "of travel";
}

// The position where the record determines it; else why not.
void place(DefectLocation &l, const PulseAreaSize &a, const Diagnosis &d, bool radial,
           const DiagnoseOptions &o)
{
  if (d.defect == "inner") {
    if (!radial)
      l.position_note = "not determined: under a balanced load every pass looks the same";
    else if (!o.shaft_angle || o.shaft_angle->empty())
      l.position_note =
          "not determined: the record has no shaft angle (angle or tachometer column)";
  } else {
    if (!radial)
      l.position_note = "not determined: under a balanced load every place looks the same";
  }
  if (!std::isfinite(a.position_deg)) {
    if (d.defect == "inner" && radial && o.shaft_angle && !o.shaft_angle->empty())
      l.position_note = "not determined: " + (a.position_note.empty() ? a.note : a.position_note);
    return;
  }
  // The model's part of the interval: the shaft's turn over half the ball's crossing of the pit
  // (the entry-to-exit width, else the pulse width): the centroid of a pulse whose height
  // changes along the crossing lies anywhere within it (as the outer place's, outer_position.h).
  const double crossing = std::isfinite(l.edge_width_s) ? l.edge_width_s
                          : d.size.valid                ? d.size.pulse_width_s
                                                        : std::nan("");
  if (!std::isfinite(crossing)) {
    l.position_note =
        "not determined: the pulses' crossing is not measured (the interval's part "
        "for the model)";
    return;
  }
  const double turn_deg = 0.5 * 360 * o.fr * crossing;
  l.position_deg = a.position_deg;
  l.position_lo_deg = wrap_deg(a.position_deg - a.position_half_deg - turn_deg);
  l.position_hi_deg = wrap_deg(a.position_deg + a.position_half_deg + turn_deg);
  l.position_reference = "shaft zero";
  l.position_note.clear();
}

}  // namespace

}  // namespace ohmdem::post
