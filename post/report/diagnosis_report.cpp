// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/diagnosis_report.h"

#include <cmath>

#include "core/constants.h"
#include "core/text_scan.h"

namespace ohmdem::post {

namespace {

Json evidence_json(const std::vector<Evidence> &ev)
{
  Json arr = Json::array();
  for (const auto &e : ev) {
    Json o = Json::object();
    o.set("spectrum", e.spectrum);
    o.set("label", e.label);
    o.set("expected_hz", e.expected_hz);
    o.set("frequency_hz", e.frequency_hz);
    o.set("amplitude", e.amplitude);
    o.set("prominence_db", e.prominence_db);
    arr.push_back(o);
  }
  return arr;
}

Json families_json(const std::vector<FamilyScore> &families)
{
  Json fams = Json::object();
  for (const auto &f : families) {
    Json o = Json::object();
    o.set("score", f.score);
    o.set("fundamental", f.label);
    o.set("nominal_hz", f.nominal_hz);
    o.set("frequency_hz", f.frequency_hz);
    o.set("comb", f.comb);
    o.set("chance", f.chance);
    o.set("margin_db", f.margin);
    o.set("harmonics", f.harmonics);
    if (std::isfinite(f.baseline_excess)) o.set("baseline_excess_db", f.baseline_excess);
    o.set("spectrum", f.spectrum);
    fams.set(f.defect, o);
  }
  return fams;
}

Json detection_json(const Detection &det, double false_alarm)
{
  Json o = Json::object();
  o.set("fired", det.fired);
  o.set("false_alarm", false_alarm);
  o.set("false_alarm_bound", det.false_alarm_bound);
  o.set("gaussian_applicable", det.gaussian_applicable);
  o.set("white_floor", det.white_floor);
  o.set("note", det.gaussian_note);
  Json arr = Json::array();
  for (const auto &t : det.tests) {
    Json e = Json::object();
    e.set("name", t.name);
    e.set("reference", t.reference);
    e.set("value", t.value);
    e.set("threshold", t.threshold);
    e.set("p_value", t.p_value);
    e.set("samples", t.samples);
    e.set("applicable", t.applicable);
    e.set("fired", t.fired);
    e.set("note", t.note);
    arr.push_back(e);
  }
  o.set("tests", arr);
  return o;
}

std::string fired_list(const Detection &det)
{
  std::string s;
  for (const auto &t : det.tests)
    if (t.fired) s += (s.empty() ? "" : "+") + t.name;
  return s.empty() ? "-" : s;
}

std::string percent_off(double f, double nominal)
{
  return format_number(100 * (f / nominal - 1), 3) + " %";
}

// The family the verdict names, if any.
const FamilyScore *chosen_family(const Diagnosis &d)
{
  const FamilyScore *chosen = nullptr;
  for (const auto &f : d.families)
    if (f.defect == d.defect || (d.defect == "ambiguous" && f.defect == d.candidate)) chosen = &f;
  if (d.defect == "other-bearing")  // the other bearing's family
    for (const auto &f : d.other_families)
      if (f.defect == d.candidate) chosen = &f;
  return chosen;
}

Json number_or_null(double v)
{
  return std::isfinite(v) ? Json(v) : Json();
}

Json pair_or_null(double lo, double hi)
{
  if (!std::isfinite(lo) && !std::isfinite(hi)) return Json();
  Json a = Json::array();
  a.push_back(number_or_null(lo));
  a.push_back(number_or_null(hi));
  return a;
}

// The size with its interval and the position (bearing/locate/defect_location.h): one answer,
// each part with its status and, when not determined, the reason.
void located_json(Json &j, const Diagnosis &d)
{
  const DefectLocation &l = d.located;
  const bool area = l.valid;
  j.set("size_deg", area ? Json(l.size_deg) : Json());
  j.set("size_interval_deg", area ? pair_or_null(l.size_lo_deg, l.size_hi_deg) : Json());
  j.set("size_status", status_name(l.size_status));
  j.set("size_method", l.method);
  j.set("size_method_name", l.size_method.empty() ? Json() : Json(l.size_method));
  j.set("size_interval_coverage",
        l.interval_coverage.empty() ? Json() : Json(l.interval_coverage));
  if (std::isfinite(l.size_reading_deg)) j.set("size_reading_deg", l.size_reading_deg);
  j.set("size_arc_m", area ? Json(l.arc_m) : Json());
  j.set("pulse_height_rel", area && l.pulse_height > 0 ? Json(l.pulse_height) : Json());
  j.set("pulse_height_source", area ? Json(l.height_source) : Json());
  j.set("pulse_window_rel_area_s", number_or_null(l.window_rel_area_s));
  // the accel-curve size method: the feature its model curve is made of (absent otherwise)
  if (std::isfinite(l.pass_energy)) j.set("pass_energy_v2s", l.pass_energy);
  j.set("pulse_edge_width_s", number_or_null(l.edge_width_s));
  j.set("position_status", status_name(l.position_status));
  j.set("place_method_name", l.place_method.empty() ? Json() : Json(l.place_method));
  j.set("position_deg", number_or_null(l.position_deg));
  j.set("position_interval_deg", pair_or_null(l.position_lo_deg, l.position_hi_deg));
  j.set("position_reference", l.position_reference.empty() ? Json() : Json(l.position_reference));
  if (std::isfinite(l.position_modulo_deg)) j.set("position_modulo_deg", l.position_modulo_deg);
  if (!l.position_note.empty()) j.set("position_note", l.position_note);
  if (std::isfinite(l.fit_angle_deg)) {
    j.set("template_angle_deg", l.fit_angle_deg);
    j.set("template_angle_interval_deg", pair_or_null(l.fit_angle_lo_deg, l.fit_angle_hi_deg));
  }
  if (!l.depth_note.empty()) j.set("depth", l.depth_note);
}

std::string interval_text(double v, double lo, double hi, const std::string &unit)
{
  return format_number(v, 4) + " " + unit + " [" +
         (std::isfinite(lo) ? format_number(lo, 4) : "-") + ", " +
         (std::isfinite(hi) ? format_number(hi, 4) : "no upper bound") + "]";
}

// The size, position and depth lines of the text (diagnose and size alike).
template <class Line>
void location_lines(const Diagnosis &d, bool chosen, Line &line)
{
  const DefectLocation &l = d.located;
  if (l.valid)
    line("size:          " +
         (l.interval_coverage.empty()
              ? format_number(l.size_deg, 4) + " deg (no interval)"
              : interval_text(l.size_deg, l.size_lo_deg, l.size_hi_deg, "deg") + " (" +
                    l.interval_coverage + ")") +
         ", arc " + format_number(l.arc_m * 1e3, 4) + " mm, by " + l.size_method + " (" +
         l.method + "; " +
         (l.pulse_height > 0 ? "jump " + format_number(l.pulse_height, 4) + ", " : std::string()) +
         l.height_source + ")");
  else if (chosen && l.size_status != LocateStatus::not_applicable && !l.method.empty())
    line("size:          " + std::string(l.method.rfind("not determined", 0) == 0 ? "" : "not determined: ") +
         l.method + (l.size_method.empty() ? "" : " (" + l.size_method + ")"));
  if (std::isfinite(d.located.position_deg))
    line("position:      " +
         interval_text(d.located.position_deg, d.located.position_lo_deg, d.located.position_hi_deg,
                       "deg") +
         " from the " + d.located.position_reference +
         (d.located.position_note.empty() ? "" : ", " + d.located.position_note));
  else if ((chosen || d.located.valid) && !d.located.position_note.empty())
    line("position:      " + d.located.position_note);
  if ((chosen || d.located.valid) && !d.located.depth_note.empty())
    line("depth:         " + d.located.depth_note);
}

}  // namespace

Json diagnosis_json(const Diagnosis &d, const DiagnosisContext &c, const MetaList &meta)
{
  const FamilyScore *chosen = chosen_family(d);
  Json j = Json::object();
  j.set("defect", d.defect);
  if (!d.candidate.empty()) {
    j.set("candidate", d.candidate);
    j.set("reason", d.reason);
  }
  j.set("detected", d.detected);
  j.set("detection", detection_json(d.detection, c.options.false_alarm));
  j.set("score", d.score);
  j.set("frequency_hz", chosen ? Json(d.frequency_hz) : Json());
  j.set("kinematic_hz", chosen ? Json(chosen->nominal_hz) : Json());
  j.set("fundamental", chosen ? Json(d.label) : Json());
  j.set("evidence", evidence_json(d.evidence));
  j.set("families", families_json(d.families));
  if (c.options.other) {
    Json o = Json::object();
    o.set("bearing", c.options.other->name);
    o.set("families", families_json(d.other_families));
    j.set("other_bearing", o);
  }
  // the pulse width measured (the area method checks its jump with it): a measurement, not a
  // size (the size is size_deg, above)
  Json pw = Json::object();
  pw.set("valid", d.size.valid);
  pw.set("method", d.size.method);
  pw.set("pulse_width_s", d.size.valid ? Json(d.size.pulse_width_s) : Json());
  pw.set("pulses", d.size.pulses);
  j.set("pulse_width", pw);
  located_json(j, d);
  Json band = Json::array();
  band.push_back(d.band.lo);
  band.push_back(d.band.hi);
  j.set("band_hz", band);
  j.set("band_kurtosis", d.band_kurtosis);
  j.set("band_kurtosis_threshold", d.band_kurtosis_threshold);
  j.set("band_kurtosis_significant",
        std::isfinite(d.band_kurtosis) ? Json(d.band_kurtosis_significant()) : Json());
  // the speed the kinematics used, the stated one and where it comes from
  j.set("shaft_hz", d.shaft_hz_used > 0 ? d.shaft_hz_used : c.options.fr);
  j.set("shaft_hz_stated", c.options.fr);
  j.set("shaft_hz_stated_source", c.speed_source);
  j.set("shaft_hz_refined", d.shaft_refined);
  j.set("shaft_hz_from_spectrum", d.shaft_estimated ? Json(d.shaft_hz_estimated) : Json());
  j.set("shaft_hz_source", d.shaft_estimated ? Json(d.shaft_source) : Json());
  j.set("domain", c.in_orders ? "orders" : "time");
  j.set("bearing", c.options.geometry.name);
  if (c.run_defect) j.set("run_defect", *c.run_defect);
  // A simulated signal at the numerical floor: its statistics describe numerical blips.
  j.set("numerical_floor", c.numerical_floor.empty() ? Json() : Json(c.numerical_floor));
  j.set("meta", meta_json(meta));
  return j;
}

Table diagnosis_row(const Diagnosis &d)
{
  const FamilyScore *chosen = chosen_family(d);
  Table t;
  t.columns = {"defect", "score", "frequency_Hz", "kinematic_Hz", "size_deg", "pulse_width_s"};
  for (const auto &f : d.families) t.columns.push_back(f.defect + "_score");
  t.columns.insert(t.columns.end(),
                   {"band_kurtosis", "band_kurtosis_threshold", "band_kurtosis_significant"});
  std::vector<Cell> row{d.defect,
                        d.score,
                        chosen ? d.frequency_hz : NAN,
                        chosen ? chosen->nominal_hz : NAN,
                        d.located.valid ? d.located.size_deg : NAN,
                        d.size.valid ? d.size.pulse_width_s : NAN};
  for (const auto &f : d.families) row.emplace_back(f.score);
  row.emplace_back(d.band_kurtosis);
  row.emplace_back(d.band_kurtosis_threshold);
  row.emplace_back(std::isfinite(d.band_kurtosis) ? (d.band_kurtosis_significant() ? "yes" : "no")
                                                  : "");
  // detection columns, appended (scripts reading the columns above keep working)
  t.columns.push_back("detected");
  row.emplace_back(d.detected ? "yes" : "no");
  t.columns.push_back("fired");
  row.emplace_back(fired_list(d.detection));
  for (const auto &test : d.detection.tests) {
    t.columns.push_back(test.name);
    t.columns.push_back(test.name + "_threshold");
    row.emplace_back(test.applicable ? test.value : NAN);
    row.emplace_back(test.applicable ? test.threshold : NAN);
  }
  // the size's interval and the position, appended
  const DefectLocation &l = d.located;
  t.columns.insert(t.columns.end(),
                   {"size_area_deg", "size_low_deg", "size_high_deg", "position_deg",
                    "position_low_deg", "position_high_deg", "position_reference"});
  row.insert(row.end(), {l.valid ? l.size_deg : NAN, l.size_lo_deg, l.size_hi_deg, l.position_deg,
                         l.position_lo_deg, l.position_hi_deg, l.position_reference});
  t.rows.push_back(row);
  return t;
}

std::vector<Block> diagnosis_text(const Diagnosis &d, const DiagnosisContext &c)
{
  const FamilyScore *chosen = chosen_family(d);
  std::vector<Block> b;
  auto line = [&b](const std::string &text) { b.push_back({text, std::nullopt}); };
  line("defect:        " + d.defect);
  if (!d.candidate.empty()) line("candidate:     " + d.candidate + " (" + d.reason + ")");
  line("detected:      " + std::string(d.detected ? "yes" : "no") +
       (d.detection.fired ? " (fired: " + fired_list(d.detection) + ")"
        : d.detected      ? " (a family identified; no detection test fired)"
                          : ""));
  line("score:         " + format_number(d.score, 3));
  if (!c.numerical_floor.empty()) line("floor:         " + c.numerical_floor);
  if (d.defect == "none" && !d.detected)
    line(std::string("verdict:       healthy: no defect family stands out of the spectrum") +
         (d.detection.fired ? "" : " and no detection test fired") +
         (c.numerical_floor.empty() ? "" : "; the signal is at the numerical floor"));
  if (chosen)
    line("frequency:     " + format_number(d.frequency_hz, 7) + " Hz = " + d.label +
         " (kinematic " + format_number(chosen->nominal_hz, 7) + " Hz, " +
         percent_off(d.frequency_hz, chosen->nominal_hz) + ")");
  location_lines(d, chosen != nullptr, line);
  line("# detection: each test at false-alarm probability " + format_number(c.options.false_alarm) +
       ", at most " + format_number(d.detection.false_alarm_bound) + " for the " +
       std::to_string(d.detection.tests_applied) + " applied; " + d.detection.gaussian_note);
  line("");
  Table dt;
  dt.columns = {"test", "against", "value", "threshold", "p_value", "samples", "fired", "note"};
  for (const auto &t : d.detection.tests)
    dt.rows.push_back({t.name, t.reference, t.value, t.threshold, t.p_value, t.samples,
                       !t.applicable ? "n/a"
                       : t.fired     ? "yes"
                                     : "no",
                       t.note.empty() ? "-" : t.note});
  b.push_back({"", dt});
  line("");
  const bool baseline = c.options.baseline != nullptr;
  Table ft;
  ft.columns = {"family",    "comb_of",    "score",      "margin_dB", "comb_dB",
                "chance_dB", "nominal_Hz", "matched_Hz", "spectrum"};
  if (baseline) ft.columns.push_back("over_baseline_dB");
  for (const auto &f : d.families) {
    ft.rows.push_back({f.defect, f.label, f.score, f.margin, f.comb, f.chance, f.nominal_hz,
                       f.frequency_hz, f.spectrum});
    if (baseline) ft.rows.back().emplace_back(f.baseline_excess);
  }
  b.push_back({"", ft});
  if (c.options.other) {
    line("");
    line("# the other bearing on the shaft: " + c.options.other->name);
    Table ot;
    ot.columns = {"other_family", "comb_of",    "score",      "margin_dB", "comb_dB",
                  "chance_dB",    "nominal_Hz", "matched_Hz", "spectrum"};
    for (const auto &f : d.other_families)
      ot.rows.push_back({f.defect, f.label, f.score, f.margin, f.comb, f.chance, f.nominal_hz,
                         f.frequency_hz, f.spectrum});
    b.push_back({"", ot});
  }
  if (!d.evidence.empty()) {
    line("");
    Table et;
    et.columns = {"evidence", "spectrum", "expected_Hz", "peak_Hz", "amplitude", "prominence_dB"};
    for (const auto &e : d.evidence)
      et.rows.push_back(
          {e.label, e.spectrum, e.expected_hz, e.frequency_hz, e.amplitude, e.prominence_db});
    b.push_back({"", et});
  }
  return b;
}

Json location_json(const Diagnosis &d, const DiagnosisContext &c, const MetaList &meta)
{
  const FamilyScore *chosen = chosen_family(d);
  Json j = Json::object();
  j.set("defect", d.defect);
  j.set("sized", c.options.assume_defect.empty() ? d.defect : c.options.assume_defect);
  j.set("frequency_hz", chosen ? Json(d.frequency_hz) : Json());
  j.set("fundamental", chosen ? Json(d.label) : Json());
  located_json(j, d);
  j.set("shaft_hz", c.options.fr);
  j.set("domain", c.in_orders ? "orders" : "time");
  j.set("bearing", c.options.geometry.name);
  if (c.run_defect) j.set("run_defect", *c.run_defect);
  j.set("meta", meta_json(meta));
  return j;
}

Table location_row(const Diagnosis &d)
{
  const DefectLocation &l = d.located;
  Table t;
  t.columns = {"defect",       "size_status",      "size_deg",          "size_low_deg",
               "size_high_deg", "size_method_name", "position_status",   "position_deg",
               "position_low_deg", "position_high_deg", "position_reference"};
  t.rows.push_back({d.defect, status_name(l.size_status), l.valid ? l.size_deg : NAN,
                    l.size_lo_deg, l.size_hi_deg, l.size_method, status_name(l.position_status),
                    l.position_deg, l.position_lo_deg, l.position_hi_deg, l.position_reference});
  return t;
}

std::vector<Block> location_text(const Diagnosis &d, const DiagnosisContext &c)
{
  const FamilyScore *chosen = chosen_family(d);
  std::vector<Block> b;
  auto line = [&b](const std::string &text) { b.push_back({text, std::nullopt}); };
  line("defect:        " + d.defect +
       (c.options.assume_defect.empty() || c.options.assume_defect == d.defect
            ? std::string()
            : " (sized as " + c.options.assume_defect + ", the assumed defect)"));
  if (chosen)
    line("frequency:     " + format_number(d.frequency_hz, 7) + " Hz = " + d.label +
         " (kinematic " + format_number(chosen->nominal_hz, 7) + " Hz, " +
         percent_off(d.frequency_hz, chosen->nominal_hz) + ")");
  location_lines(d, chosen != nullptr || !c.options.assume_defect.empty(), line);
  if (d.located.size_status == LocateStatus::not_applicable && !chosen)
    line("size:          not applicable (no race defect identified)");
  return b;
}

}  // namespace ohmdem::post
