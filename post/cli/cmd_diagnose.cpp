// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post diagnose: detection (is something wrong), then the most likely bearing defect,
// its score, evidence and size.
#include <cmath>
#include <iostream>

#include "bearing/diagnose.h"
#include "bearing/order_diagnose.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "cli/shaft_angle.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/text_scan.h"

namespace ohmdem::post::cli {

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

// What the three forms of the diagnosis show besides the Diagnosis itself.
struct DiagnosisContext {
  const DiagnoseOptions &options;
  bool in_orders;
  std::optional<std::string> run_defect;  // run.json "defect": what the run simulated
};

// The family the verdict names, if any.
const FamilyScore *chosen_family(const Diagnosis &d)
{
  const FamilyScore *chosen = nullptr;
  for (const auto &f : d.families)
    if (f.defect == d.defect) chosen = &f;
  return chosen;
}

Json diagnosis_json(const Diagnosis &d, const DiagnosisContext &c, const MetaList &meta)
{
  const FamilyScore *chosen = chosen_family(d);
  Json j = Json::object();
  j.set("defect", d.defect);
  j.set("detected", d.detected);
  j.set("detection", detection_json(d.detection, c.options.false_alarm));
  j.set("score", d.score);
  j.set("frequency_hz", chosen ? Json(d.frequency_hz) : Json());
  j.set("kinematic_hz", chosen ? Json(chosen->nominal_hz) : Json());
  j.set("fundamental", chosen ? Json(d.label) : Json());
  j.set("evidence", evidence_json(d.evidence));
  Json fams = Json::object();
  for (const auto &f : d.families) {
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
  j.set("families", fams);
  Json sz = Json::object();
  sz.set("valid", d.size.valid);
  sz.set("method", d.size.method);
  sz.set("pulse_width_s", d.size.valid ? Json(d.size.pulse_width_s) : Json());
  sz.set("size_deg", d.size.valid ? Json(d.size.size_deg) : Json());
  sz.set("arc_m", d.size.valid ? Json(d.size.arc_m) : Json());
  sz.set("pulses", d.size.pulses);
  j.set("size", sz);
  Json band = Json::array();
  band.push_back(d.band.lo);
  band.push_back(d.band.hi);
  j.set("band_hz", band);
  j.set("band_kurtosis", d.band_kurtosis);
  j.set("band_kurtosis_threshold", d.band_kurtosis_threshold);
  j.set("band_kurtosis_significant",
        std::isfinite(d.band_kurtosis) ? Json(d.band_kurtosis_significant()) : Json());
  j.set("shaft_hz", c.options.fr);
  j.set("domain", c.in_orders ? "orders" : "time");
  j.set("bearing", c.options.geometry.name);
  if (c.run_defect) j.set("run_defect", *c.run_defect);
  j.set("meta", meta_json(meta));
  return j;
}

// One row for tables of many records: the verdict, the family scores, the detection tests.
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
                        d.size.valid ? d.size.size_deg : NAN,
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
  t.rows.push_back(row);
  return t;
}

// For reading: the verdict, then the detection tests, the families and the evidence.
std::vector<Block> diagnosis_text(const Diagnosis &d, const DiagnosisContext &c)
{
  const FamilyScore *chosen = chosen_family(d);
  std::vector<Block> b;
  auto line = [&b](const std::string &text) { b.push_back({text, std::nullopt}); };
  line("defect:        " + d.defect);
  line("detected:      " + std::string(d.detected ? "yes" : "no") +
       (d.detection.fired ? " (fired: " + fired_list(d.detection) + ")"
        : d.detected      ? " (a family identified; no detection test fired)"
                          : ""));
  line("score:         " + format_number(d.score, 3));
  if (chosen)
    line("frequency:     " + format_number(d.frequency_hz, 7) + " Hz = " + d.label +
         " (kinematic " + format_number(chosen->nominal_hz, 7) + " Hz, " +
         percent_off(d.frequency_hz, chosen->nominal_hz) + ")");
  if (d.size.valid)
    line("size:          " + format_number(d.size.size_deg, 4) + " deg, arc " +
         format_number(d.size.arc_m * 1e3, 4) + " mm (pulse width " +
         format_number(d.size.pulse_width_s * 1e6, 4) + " us, " + d.size.method + ", " +
         std::to_string(d.size.pulses) + (d.size.method == "pulses" ? " pulses" : " periods") +
         ")");
  else if (chosen)
    line("size:          n/a (" + d.size.method + ")");
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

}  // namespace

int run_diagnose(const std::vector<std::string> &argv)
{
  Args a(
      "diagnose", "[options] FILE...",
      "Detection, then identification. Detection tests whether the record is unlike a\n"
      "healthy one: kurtosis, crest factor and the spectral kurtosis of the envelope band\n"
      "against the Gaussian law (records with a noise floor), and with --baseline the RMS,\n"
      "kurtosis, crest and band energy against a healthy record's window-to-window scatter;\n"
      "each test at the false-alarm probability --false-alarm. Identification finds the peaks\n"
      "of the spectrum and of the envelope spectrum (band from the kurtogram unless --band),\n"
      "matches them to the defect families - inner race (BPFI, shaft sidebands), outer race\n"
      "(BPFO), ball (2xBSF, cage sidebands), cage (FTF) - with harmonic combs whose fundamental\n"
      "may be off by --tolerance (slip). The defect is the family scoring >= --min-score\n"
      "(inner, outer, ball, cage), else 'unidentified' if detection fired (a fault of unknown\n"
      "type), else 'none'; with a score in [0, 1] and the matched peaks. The defect size is\n"
      "estimated from the pulse widths of a level signal such as R(t).\n"
      "For our runs, bearing, speed and the end of the sliding phase come from run.json.");
  add_input_options(a);
  add_bearing_options(a);
  add_shaft_angle_options(a);
  a.section("Diagnosis");
  a.option("--tolerance", "F", "relative search range of each fundamental (slip), in (0, 0.2)",
           "0.02");
  a.option("--harmonics", "N", "harmonics in each family's comb (1..50)", "5");
  a.option("--min-score", "S", "below this score the defect is 'none'", "0.3");
  a.option("--band", "F1 F2", "envelope band (Hz) instead of the kurtogram's", "", 2);
  a.option("--levels", "N", "kurtogram levels (0..16)", "7");
  a.section("Detection");
  a.option("--false-alarm", "P", "false-alarm probability of each detection test", "0.001");
  a.option("--baseline", "FILE",
           "healthy reference record (same input options and sampling rate; its run.json is "
           "not read)");
  a.flag("--no-size", "skip the defect size estimate");
  a.flag("--keep-sliding",
         "analyse the sliding phase too (default: start at t_sliding_end "
         "of run.json)");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  const Signal s = load_input(a, meta, 256, !a.has("--keep-sliding"));
  const BearingChoice bc = bearing_choice(a, meta);
  if (!bc.geometry)
    throw Error(
        "diagnose: give the bearing (--bearing NAME of the catalog, or --nb --db --dp) or a "
        "run.json with it");
  // order tracking (issue 17): an angle/speed column whose speed varies by more than --tolerance
  // switches the diagnosis to the angle domain
  const std::optional<ShaftAngle> sa = measured_shaft_angle(a, meta, s);
  if (!bc.fr && !sa)
    throw Error(
        "diagnose: give the shaft speed (--rpm, --shaft-hz or --omega) or a run.json "
        "with omega_inner");
  DiagnoseOptions o;
  o.geometry = *bc.geometry;
  o.fr = bc.fr ? *bc.fr : sa->speed.mean / (2 * kPi);
  o.tolerance = tolerance_option(a);
  o.harmonics = harmonics_option(a, 5);
  o.min_score = a.number("--min-score", 0.3);
  o.kurtogram_levels = levels_option(a);
  if (a.has("--band")) o.band = band_option(a);
  o.estimate_size = !a.has("--no-size");
  o.false_alarm = a.number_in("--false-alarm", 1e-3, Range::open(0, 0.5), "a probability");
  Signal base;
  if (a.has("--baseline")) {
    // the record's input options and time window (its sliding phase too), its step length
    InputOptions io = input_options(a);
    io.files = {a.get("--baseline")};
    io.min_samples = 256;
    if (!a.has("--from") && !a.has("--keep-sliding") && meta.t_sliding_end)
      io.from = *meta.t_sliding_end;
    base = load_named(io, meta);
    o.baseline = &base;
  }
  const bool in_orders = sa && sa->speed.variation > o.tolerance;
  if (in_orders && o.baseline)
    throw Error(
        "diagnose: --baseline is not supported when the speed varies (the record is "
        "diagnosed in the angle domain); give a record at constant speed");
  const Diagnosis d = in_orders ? diagnose_in_orders(s, sa->theta, o) : diagnose(s, o);
  if (in_orders) o.fr = sa->speed.mean / (2 * kPi);
  for (const auto &w : d.warnings) std::cerr << "WARNING: diagnose: " << w << "\n";
  Output out(a);

  MetaList m = s.meta;
  m.emplace_back("bearing", o.geometry.name + " (" + bc.geometry_source + ")");
  m.emplace_back(
      "shaft frequency (Hz)",
      format_number(o.fr, 8) + " (" + (in_orders ? "mean of " + sa->source : bc.fr_source) + ")");
  if (in_orders)
    m.emplace_back("domain", "orders: speed varies by " +
                                 format_number(100 * sa->speed.variation, 3) +
                                 " % > --tolerance; resampled at constant shaft angle, "
                                 "frequencies = orders x mean shaft frequency");
  m.emplace_back("envelope band (Hz)",
                 format_number(d.band.lo) + " to " + format_number(d.band.hi) +
                     (std::isfinite(d.band_kurtosis) ? " (kurtogram, spectral kurtosis " +
                                                           format_number(d.band_kurtosis, 4) + ")"
                                                     : " (--band)"));
  if (o.baseline) m.emplace_back("baseline", a.get("--baseline"));
  if (std::isfinite(d.band_kurtosis))  // issue 17: is the best band more than noise?
    m.emplace_back("band kurtosis significant",
                   std::string(d.band_kurtosis_significant() ? "yes" : "no") + " (Gaussian-noise " +
                       "threshold " + format_number(d.band_kurtosis_threshold, 4) +
                       " at alpha 0.01 over the bands searched)");
  Result r;
  r.meta = std::move(m);
  const DiagnosisContext ctx{o, in_orders, meta.defect};
  r.json = diagnosis_json(d, ctx, r.meta);
  r.table = diagnosis_row(d);
  r.text = diagnosis_text(d, ctx);
  out.write(r);
  return 0;
}

}  // namespace ohmdem::post::cli
