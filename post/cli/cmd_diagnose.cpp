// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post diagnose: detection (is something wrong), then the most likely bearing defect,
// its score, evidence and size.
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bearing/diagnose.h"
#include "bearing/locate/locate.h"
#include "bearing/order_diagnose.h"
#include "bearing/pulse_template.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "cli/other_channel_input.h"
#include "cli/shaft_angle.h"
#include "cli/model_cache.h"
#include "cli/model_input.h"
#include "cli/template_bank_input.h"
#include "core/constants.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/settle.h"
#include "dsp/stats.h"
#include "report/diagnosis_report.h"

namespace ohmdem::post::cli {

namespace {

// The detection's notes name settings ("{detect.baseline}"): the user reads the flags.
void name_flags(Detection &det)
{
  det.gaussian_note = flag_named(det.gaussian_note);
  for (DetectionTest &t : det.tests) t.note = flag_named(t.note);
}

// --mains: positive frequencies, comma-separated, or none.
std::vector<double> mains_option(const std::string &text)
{
  std::vector<double> hz;
  if (text == "none") return hz;
  for (const std::string &item : split_commas(text)) {
    double f = 0;
    if (!parse_double(item, f) || !std::isfinite(f) || !(f > 0))
      throw Error(
          "--mains expects mains frequencies in Hz, comma-separated (e.g. 50 or 50,60), "
          "or 'none', got '" +
          text + "'");
    hz.push_back(f);
  }
  if (hz.empty())
    throw Error(
        "--mains expects mains frequencies in Hz, comma-separated (e.g. 50 or 50,60), "
        "or 'none', got '" +
        text + "'");
  return hz;
}

// A simulated R that varies by less than kFloor of its mean is at the numerical floor of the
// run: the demo's 1-degree inner-race pit gives a spread (std/mean) of 1.4e-2, the healthy
// 6208 3.2e-7 (one 2e-5 ohm blip then makes a kurtosis of 1520 and a p-value of 1e-279).
// kFloor = 1e-5 lies three orders of magnitude under the smallest defect's signature.
std::string numerical_floor(const Signal &s, const RunMetadata &meta)
{
  constexpr double kFloor = 1e-5;
  if (!meta.present() || s.x.empty()) return "";
  const Indicators ind = indicators(s.x);
  const double spread = ind.std / std::fabs(ind.mean);
  if (!(spread < kFloor)) return "";
  return s.name + " varies by " + format_number(spread, 2) + " of its mean (std " +
         format_number(ind.std, 2) +
         "): the numerical floor of the simulation, far below a defect's signature (1e-2 for a "
         "1-degree pit); the statistics below describe numerical blips, not a defect";
}

std::string size_method_help()
{
  std::string h = "how the size is read (default: chosen by the record: template with a "
                  "--template-bank, else area on an electrical level record; accel-curve with a "
                  "--size-curve, else double-impulse on a vibration record):";
  for (const SizeMethod *m : size_methods()) h += std::string(" ") + m->name() + " (" + flag_named(m->summary()) + ");";
  h.back() = '.';
  return h;
}

std::string place_method_help()
{
  std::string h = "how the place is read (default: pulses on an electrical level record, passes "
                  "on a vibration record):";
  for (const PlaceMethod *m : place_methods()) h += std::string(" ") + m->name() + " (" + flag_named(m->summary()) + ");";
  h.back() = '.';
  return h;
}

// Our run's record from the end of its sliding phase, and under a radial load past the
// start-up transient that follows it while the free outer ring finds its place (dsp/settle.h:
// the level's drift, in windows of one shaft revolution), unless --from or --keep-sliding say
// where to start; meta's t_sliding_end moves with it (the companion channels and the baseline
// start there too).
Signal settled_input(const Args &a, RunMetadata &meta, const BearingChoice &bc)
{
  Signal s = load_input(a, meta, 256, !a.has("--keep-sliding"));
  if (a.has("--from") || a.has("--keep-sliding") || !meta.t_sliding_end || !bc.fr ||
      meta.load.value_or("") != "radial")
    return s;
  const auto window = static_cast<std::size_t>(std::lround(s.rate / *bc.fr));
  if (window < 2) return s;
  const Settling st = settled_start(s.x, window);
  const double sliding_end = *meta.t_sliding_end;
  if (st.start > 0) {
    meta.t_sliding_end = s.time(st.start) - 0.5 / s.rate;
    s = load_input(a, meta, 256, true);
  }
  for (auto &[key, value] : s.meta)
    if (key == "sliding phase skipped")
      value = "t < " + format_number(sliding_end) + " s" +
              (st.start == 0
                   ? ""
                   : "; settling transient skipped: t < " + format_number(s.t0) +
                         " s (the level drifts by " + format_number(st.first_drift, 3) +
                         " against a per-revolution scatter of " + format_number(st.scatter, 3) +
                         " afterwards)");
  return s;
}

}  // namespace

namespace {

const char *const kSizeHelp =
    "The size and place of a bearing's race defect: the record is diagnosed as by diagnose\n"
    "(its options), then the defect found (or --assume-defect) is sized and placed by the\n"
    "methods the record calls for (an electrical level record: its pulses' area or, with a\n"
    "bank, their shape; a vibration record: its passes), or by --size-method and\n"
    "--place-method. --model FILE gives the model data made of the record's scene (a bank of\n"
    "pulse templates, or a curve), whatever its kind: the header says which. A size is\n"
    "printed only inside the validity its method's report measured, its interval labelled\n"
    "with the coverage measured; elsewhere 'not determined' with the reason.\n"
    "For our runs, bearing, speed, load and the end of the sliding phase come from run.json.\n"
    "Example: ohmdem-post size V.txt --metadata run.json --model bank_inner_fixed_r20000_low.txt";

int run_located(const std::vector<std::string> &argv, bool size_only)
{
  Args a(
      size_only ? "size" : "diagnose", "[options] FILE...",
      size_only ? kSizeHelp :
      "Detection, then identification. Detection tests whether the record is unlike a\n"
      "healthy one: kurtosis, crest factor and the spectral kurtosis of the envelope band\n"
      "against the Gaussian law (records with a noise floor), and with --baseline the RMS,\n"
      "kurtosis, crest and band energy against a healthy record's window-to-window scatter;\n"
      "each test at the false-alarm probability --false-alarm. Identification finds the peaks\n"
      "of the spectrum and of the envelope spectrum (band from the kurtogram unless --band),\n"
      "matches them to the defect families - inner race (BPFI, shaft sidebands), outer race\n"
      "(BPFO), ball (2xBSF, cage sidebands), cage (FTF) - with harmonic combs whose fundamental\n"
      "may be off by --tolerance (slip); shaft and mains lines are masked. The stated speed\n"
      "(run.json, --rpm, --shaft-hz, --omega, a tachometer) is used, refined by the shaft comb\n"
      "within --speed-refine where it stands out. The defect is the family scoring >=\n"
      "--min-score (inner, outer, ball, cage), 'ambiguous' if its order lies within half the\n"
      "tolerance of a shaft harmonic unless its comb sits at its kinematic value,\n"
      "'other-bearing' if --other-bearing's comb explains the record better than\n"
      "any of this bearing's, else 'unidentified' if detection fired (a fault of unknown\n"
      "type), else 'none'; with a score in [0, 1] and the matched peaks. The defect's size and\n"
      "place follow from the methods the record calls for, a size only inside the validity its\n"
      "method's report measured (else 'not determined' with the reason); an inner defect is\n"
      "placed on the ring from the shaft angle under a radial load.\n"
      "For our runs, bearing, speed and the end of the sliding phase come from run.json (under\n"
      "a radial load the start-up transient after it is skipped too).\n"
      "Size and place: the options below, or ohmdem-post size (the same, its answer alone).\n"
      "Reference: doc/post/diagnose.md, doc/post/size.md.");
  add_input_options(a);
  add_bearing_options(a);
  add_shaft_angle_options(a);
  a.section("Diagnosis");
  a.option("--tolerance", "F", "relative search range of each fundamental (slip), in (0, 0.2)",
           "0.02");
  a.option("--speed-refine", "F",
           "the spectrum's shaft comb may move the stated speed (run.json, --rpm, --shaft-hz, "
           "--omega, a tachometer) by at most this fraction, where the comb stands out, in "
           "[0, --tolerance]; 0: the stated speed as it is",
           "0.002");
  a.option("--harmonics", "N", "harmonics in each family's comb (1..50)", "5");
  a.option("--min-score", "S", "below this score the defect is 'none'", "0.3");
  a.option("--band", "F1 F2", "envelope band (Hz) instead of the kurtogram's", "", 2);
  a.option("--levels", "N", "kurtogram levels (0..16)", "7");
  a.option("--other-bearing", "NAME",
           "the other bearing on the same shaft (catalog name, e.g. 6205-2RS_JEM, the CWRU drive "
           "end, when the record is the fan end's): a record whose impulses are at its defect "
           "frequencies reads 'other-bearing', not 'unidentified'");
  add_other_channel_options(a);
  add_across_options(a);
  a.option("--mains", "LIST",
           "mains frequencies (Hz, comma-separated) whose harmonic combs are masked where they "
           "stand out, or 'none'",
           "50,60");
  a.section("Detection");
  a.option("--false-alarm", "P", "false-alarm probability of each detection test", "0.001");
  a.option("--baseline", "FILE",
           "healthy reference record (same input options and sampling rate; its run.json is "
           "not read)");
  a.option("--baseline-rate", "HZ",
           "sampling rate of a --baseline without time stamps when it is not the record's: "
           "refused if it differs (resample it first with acquire)");
  a.section("Size and place");
  a.option("--model", "FILE[,FILE]",
           "the model data of the record's scene, of any kind (the file's header says which): a "
           "bank of pulse templates (studies/template_bank.py), a curve of the pulse area, of the "
           "pulses' entry-to-exit width or of the pass energy (studies/sizing.py), their "
           "model errors read from their headers");
  a.flag("--no-size", "skip the defect size estimate");
  a.option("--load", "MODE",
           "how the bearing is loaded (force, fixed or radial; default: run.json's load): "
           "the pulse-area size needs it");
  a.option("--assume-defect", "KIND",
           "size and place this race defect (inner or outer, at its kinematic frequency) "
           "even when the identification names another or none");
  a.option("--size-curve", "FILE",
           "the model's curve from simulations of the same scene: lines 'SIZE_DEG AREA_S' (the "
           "fixed-window pulse area over the level, JSON pulse_window_rel_area_s), both "
           "increasing; the size is read off it");
  a.option("--size-model-error", "REL",
           "the --size-curve's own error, the relative standard deviation of its area (from "
           "simulations the curve does not use; sizing.py writes it in the curve's header): "
           "the size's interval includes it (default 0: the pass-to-pass scatter only)");
  a.option("--size-method", "METHOD", size_method_help());
  a.option("--place-method", "METHOD", place_method_help());
  a.option("--template-bank", "FILE",
           "the model's pulse templates for --size-method template: folds of simulations of the "
           "same scene at known sizes (and angles from the load) through the record's chain "
           "(studies/template_bank.py writes it)");
  a.option("--pulse-fold-out", "FILE",
           "write the record's pulse fold at the defect's frequency (relative to the level, per "
           "1/4 sample: lines 'Y SE'), from which studies/template_bank.py makes a bank");
  a.option("--fold-period", "grid|fine",
           "the period the record is folded at for --size-method template and --pulse-fold-out: "
           "grid (the repetition of highest contrast on a grid whose step drifts the fold by "
           "1/20 period over the record) or fine (then refined on the first harmonics' power, "
           "to under 1/10^4 period); default: the --template-bank's '# fold period:', else grid");
  a.option("--width-curve", "FILE",
           "the model's width curve from simulations of the same scene through the record's "
           "chain: lines 'SIZE_DEG WIDTH_S' (the pulses' entry-to-exit width, JSON "
           "pulse_edge_width_s), both increasing; where the record's width lies on it, the size "
           "is read off it instead of the area's curve");
  a.option("--width-model-error", "REL",
           "the --width-curve's own relative error (sizing.py writes it in the curve's header)");
  a.option("--pulse-height", "H",
           "relative jump of the level when the defect's ball loses contact (at the load "
           "zone's centre under a radial load), from a simulation of the scene; default under "
           "a balanced load: 1/(Nb-1)");
  a.flag("--keep-sliding",
         "analyse the sliding phase too (default: start at t_sliding_end "
         "of run.json)");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  RunMetadata meta = run_metadata(a);
  const BearingChoice bc = bearing_choice(a, meta);
  const Signal s = settled_input(a, meta, bc);
  if (!bc.geometry)
    throw Error(
        "diagnose: give the bearing (--bearing NAME of the catalog, or --nb --db --dp) or a "
        "run.json with it");
  // order tracking: an angle/speed column whose speed varies by more than --tolerance
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
  o.speed_refine = a.number_in("--speed-refine", 0.002, Range::closed(0, o.tolerance),
                               "a fraction of the stated speed (at most --tolerance)");
  o.harmonics = harmonics_option(a, 5);
  o.min_score = a.number("--min-score", 0.3);
  o.kurtogram_levels = levels_option(a);
  if (a.has("--band")) o.band = band_option(a);
  o.estimate_size = !a.has("--no-size");
  o.load = a.has("--load") ? a.get("--load") : meta.load.value_or("");
  if (!o.load.empty() && o.load != "force" && o.load != "fixed" && o.load != "radial")
    throw Error(std::string("diagnose: ") +
                (a.has("--load") ? "--load" : meta.path + "'s \"load\"") +
                " must be force, fixed or radial, got '" + o.load + "'");
  if (a.has("--pulse-height"))
    o.pulse_height = a.number_in("--pulse-height", 0, Range::open(0, 10), "a relative jump");
  if (sa) o.shaft_angle = &sa->theta;
  if (const auto files = input_options(a).files; !files.empty()) {
    o.record_filter = record_filter(files[0]);
    if (o.record_filter)
      o.record_delay_s = sos_dc_delay_s(o.record_filter->sos, o.record_filter->fs);
  }
  // the size and place methods, by name from their tables (bearing/locate/size_method.h)
  if (a.has("--size-method")) o.size_method = &size_method(a.get("--size-method"));
  if (a.has("--place-method")) o.place_method = &place_method(a.get("--place-method"));
  std::optional<BankFile> bank;
  ModelFiles model;
  if (a.has("--model")) {
    for (const char *given : {"--template-bank", "--size-curve", "--width-curve",
                              "--size-model-error", "--width-model-error"})
      if (a.has(given))
        throw Error(std::string("diagnose: --model and ") + given +
                    " give the model data twice: give --model alone");
    model = read_models(split_commas(a.get("--model")));
  }
  if (model.bank) bank = std::move(model.bank);
  if (!model.curve_value.empty()) {
    if ((model.curve_feature == "pass energy") != (record_kind(s.x) == RecordKind::vibration))
      throw Error("diagnose: --model: a curve of the " + model.curve_feature + " is for " +
                  (model.curve_feature == "pass energy" ? "a vibration" : "an electrical level") +
                  " record; this record is a " + kind_name(record_kind(s.x)) + " record");
    o.curve_size_deg = model.curve_size_deg;
    o.curve_rel_area_s = model.curve_value;
    o.curve_rel_error = model.curve_rel_error;
  }
  o.width_curve_size_deg = model.width_size_deg;
  o.width_curve_s = model.width_s;
  o.width_rel_error = model.width_rel_error;
  if (bank) {
    check_bank(*bank, s, input_options(a).files.at(0), &*bc.geometry, "", o.load);
    o.template_bank = &bank->bank;
    o.fine_fold_period = bank->fine_fold_period;
  }
  if (a.has("--template-bank")) {
    bank = read_template_bank(a.get("--template-bank"));
    check_bank(*bank, s, input_options(a).files.at(0), &*bc.geometry, "", o.load);
    o.template_bank = &bank->bank;
    o.fine_fold_period = bank->fine_fold_period;
  }
  if (a.has("--fold-period")) {
    const std::string how = a.get("--fold-period");
    if (how != "grid" && how != "fine")
      throw Error("diagnose: --fold-period must be grid or fine, got '" + how + "'");
    // a record folded otherwise than its bank's templates would differ from them by the smear
    if (bank && (how == "fine") != bank->fine_fold_period)
      throw Error("diagnose: --fold-period " + how +
                  ": the --template-bank's folds were made at the " +
                  (bank->fine_fold_period ? "fine" : "grid") +
                  " period (its '# fold period:' line; absent: grid): fold the record alike");
    o.fine_fold_period = how == "fine";
  }
  if (a.has("--size-curve"))  // accel-curve: the passes' energy against size, else the area
    read_curve(a.get("--size-curve"), "--size-curve",
               record_kind(s.x) == RecordKind::vibration ? "ENERGY_V2S" : "AREA_S",
               o.curve_size_deg, o.curve_rel_area_s);
  if (a.has("--width-curve"))
    read_curve(a.get("--width-curve"), "--width-curve", "WIDTH_S", o.width_curve_size_deg,
               o.width_curve_s);
  if (a.has("--width-model-error")) {
    if (!a.has("--width-curve"))
      throw Error("diagnose: --width-model-error needs --width-curve (it is the curve's error)");
    o.width_rel_error =
        a.number_in("--width-model-error", 0, Range::closed(0, 1), "a relative error");
  }
  if (a.has("--size-model-error")) {
    if (!a.has("--size-curve"))
      throw Error("diagnose: --size-model-error needs --size-curve (it is the curve's error)");
    o.curve_rel_error =
        a.number_in("--size-model-error", 0, Range::closed(0, 1), "a relative error");
  }
  if (a.has("--assume-defect")) {
    o.assume_defect = a.get("--assume-defect");
    if (o.assume_defect != "inner" && o.assume_defect != "outer")
      throw Error("diagnose: --assume-defect must be inner or outer, got '" + o.assume_defect +
                  "'");
  }
  o.false_alarm = a.number_in("--false-alarm", 1e-3, Range::open(0, 0.5), "a probability");
  if (a.has("--mains")) o.mains_hz = mains_option(a.get("--mains"));
  std::string other_source;
  if (a.has("--other-bearing")) {
    const std::string catalog = a.has("--catalog") ? a.get("--catalog") : default_catalog_dir();
    const CatalogEntry e = catalog_entry(catalog, a.get("--other-bearing"));
    try {  // its own --dp would not apply: the entry must fix the frequencies by itself
      o.other = e.geometry();
    } catch (const Error &) {
      throw Error("--other-bearing " + a.get("--other-bearing") + " (" + e.path +
                  ") does not fix its defect frequencies (no pitch diameter and no factors): give "
                  "a catalog bearing with Z, Dw and Dpw, or with the maker's factors");
    }
    validate(*o.other);
    other_source = e.path;
  }
  Signal base;
  if (a.has("--baseline")) {
    // the record's input options and time window (its sliding phase too), its step length
    InputOptions io = input_options(a);
    io.files = {a.get("--baseline")};
    io.min_samples = 256;
    if (a.has("--baseline-rate"))
      io.rate = a.number_in("--baseline-rate", 0, Range::above(0), "a rate", "Hz");
    if (!a.has("--from") && !a.has("--keep-sliding") && meta.t_sliding_end)
      io.from = *meta.t_sliding_end;
    base = load_named(io, meta);
    // a healthy record at another rate would be compared line by line at wrong frequencies:
    // refused, never resampled silently
    if (std::fabs(base.rate / s.rate - 1) > 1e-9) {
      // the command that brings the faster of the two to the slower one's rate, as acquire
      // takes it: the file's column, its rate when it has no time stamps, a filter below the
      // new Nyquist frequency (0.4 of the rate), the new record's column named so that the
      // record's own column option selects it in both files
      const bool base_faster = base.rate > s.rate;
      const Signal &fast = base_faster ? base : s;
      const double slow_rate = base_faster ? s.rate : base.rate;
      const std::string path = base_faster ? io.files[0] : input_options(a).files.at(0);
      const bool rated = a.has("--rate") || a.has("--rate-variable");
      const bool stamped = base_faster ? !a.has("--baseline-rate") && !rated : !rated;
      auto word = [](const std::string &w) {
        if (!w.empty() && w.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                              "0123456789_./+-") == std::string::npos)
          return w;
        std::string q = "'";
        for (char c : w) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q + "'";
      };
      const std::string given = a.has("--column")     ? a.get("--column")
                                : a.has("--variable") ? a.get("--variable")
                                                      : "";
      const bool headerless = s.name == "x" || s.name.rfind("column ", 0) == 0;
      const std::string name = !given.empty() ? given : headerless ? "1" : s.name;
      std::string stem = path.substr(path.find_last_of('/') + 1);
      stem = stem.substr(0, stem.find_last_of('.'));
      const std::string resampled = stem + "_" + format_number(slow_rate, 10) + "Hz.txt";
      const std::string cmd =
          "ohmdem-post acquire " + word(path) + (given.empty() ? "" : " --column " + word(given)) +
          (stamped ? "" : " --input-rate " + format_number(fast.rate, 10)) + " --lowpass " +
          format_number(0.4 * slow_rate, 10) + " --rate " + format_number(slow_rate, 10) +
          " --name " + word(name) + " --output " + word(resampled);
      throw Error("diagnose: --baseline " + io.files[0] + " is sampled at " +
                  format_number(base.rate, 10) + " Hz, the record at " + format_number(s.rate, 10) +
                  " Hz: a baseline must have the record's rate; " +
                  (base_faster
                       ? "resample the baseline to it: " + cmd +
                             ", then diagnose with --baseline " + word(resampled) +
                             (given.empty() ? " --column " + word(name) : "") +
                             " (no --baseline-rate)"
                       : "resample the record to the baseline's rate: " + cmd + ", then diagnose " +
                             word(resampled) + " with the same --baseline" +
                             (rated ? " (no --rate: it has time stamps)" : "")));
    }
    o.baseline = &base;
  }
  const std::optional<Signal> other_channel = other_channel_input(a, meta, s);
  if (other_channel) o.other_channel = &*other_channel;
  const std::optional<Signal> across = across_input(a, meta, s);
  if (across) o.across = &*across;
  const bool in_orders = sa && sa->speed.variation > o.tolerance;
  std::string no_size, m_cached_bank;
  if (o.estimate_size) {
    // the method's own check of the settings, and what it needs of the record
    const SizeMethod &sm = o.size_method ? *o.size_method : default_size_method(s, o);
    sm.check(o);
    if (in_orders && sm.needs().constant_speed) {
      const std::string why = "the " + std::string(sm.name()) +
                              " size method needs a record at constant speed (the speed varies "
                              "by " +
                              format_number(100 * sa->speed.variation, 3) + " % > --tolerance)";
      if (o.size_method) throw Error("diagnose: " + why);
      no_size = why;  // the method the record chose: said in the output, not refused
      o.estimate_size = false;
    }
    if (bank) {
      const std::string sized = o.assume_defect;
      if (sized == "inner" || sized == "outer") check_bank(*bank, s, "", nullptr, sized, "");
    }
  }
  if (in_orders && o.baseline)
    throw Error(
        "diagnose: --baseline is not supported when the speed varies (the record is "
        "diagnosed in the angle domain); give a record at constant speed");
  Diagnosis d = in_orders ? diagnose_in_orders(s, sa->theta, o) : diagnose(s, o);
  if (!no_size.empty() && (d.defect == "inner" || d.defect == "outer")) {
    d.located.size_status = d.located.position_status = LocateStatus::not_determined;
    d.located.method = "not determined: " + no_size;
    d.located.position_note = "not determined: " + no_size;
  }
  // no model data given: the bank ohmdem-post model made of this scene, when cached
  const bool given = a.has("--model") || a.has("--template-bank") || a.has("--size-curve") ||
                     a.has("--width-curve") || a.has("--pulse-height") || a.has("--size-method");
  const std::string sized = o.assume_defect.empty() ? d.defect : o.assume_defect;
  if (!given && o.estimate_size && !in_orders && meta.present() &&
      (sized == "inner" || sized == "outer") && record_kind(s.x) == RecordKind::level) {
    std::string cached;
    try {
      cached = cached_bank_path(record_scene(input_options(a).files.at(0), meta, sized,
                                             default_bank_sizes(), kDefaultRunLength,
                                             kDefaultHeldOut));
    } catch (const Error &) {
      cached.clear();  // a scene the model command cannot make: nothing cached for it
    }
    if (!cached.empty() && access(cached.c_str(), R_OK) == 0) {
      bank = read_template_bank(cached);
      check_bank(*bank, s, input_options(a).files.at(0), &*bc.geometry, sized, o.load);
      o.template_bank = &bank->bank;
      o.fine_fold_period = bank->fine_fold_period;
      d.located = locate(s, d, o);
      m_cached_bank = cached;
    }
  }
  if (bank && o.assume_defect.empty() && (d.defect == "inner" || d.defect == "outer"))
    check_bank(*bank, s, "", nullptr, d.defect, "");
  if (a.has("--pulse-fold-out")) {
    refuse_input_as_output("--pulse-fold-out", a.get("--pulse-fold-out"),
                           input_files(a, "--pulse-fold-out"));
    write_fold(a.get("--pulse-fold-out"), record_fold(s, d, o), input_options(a).files.at(0));
  }
  name_flags(d.detection);
  d.located.method = flag_named(d.located.method);
  d.located.height_source = flag_named(d.located.height_source);
  d.located.position_note = flag_named(d.located.position_note);
  if (in_orders) o.fr = sa->speed.mean / (2 * kPi);
  for (const auto &w : d.warnings) std::cerr << "WARNING: diagnose: " << w << "\n";
  Output out(a);

  MetaList m = s.meta;
  if (!m_cached_bank.empty())
    m.emplace_back("model", m_cached_bank + " (the cached bank of this scene, ohmdem-post model)");
  m.emplace_back("bearing", o.geometry.name + " (" + bc.geometry_source + ")");
  if (o.other)
    m.emplace_back("other bearing on the shaft", o.other->name + " (" + other_source + ")");
  const std::string speed_source = in_orders || !bc.fr ? "mean of " + sa->source : bc.fr_source;
  m.emplace_back("shaft frequency stated (Hz)", format_number(o.fr, 8) + " (" + speed_source + ")");
  m.emplace_back("shaft frequency used (Hz)",
                 format_number(d.shaft_hz_used, 8) +
                     (d.shaft_refined
                          ? " (the stated one refined by the shaft comb by " +
                                format_number(100 * (d.shaft_hz_used / o.fr - 1), 3) +
                                " %, within the +-" + format_number(100 * o.speed_refine, 3) +
                                " % --speed-refine allows)"
                          : " (the stated one)"));
  // the shaft frequency the spectrum's own shaft harmonics give (a tachometer off by
  // a percent or two), and the shaft and mains lines no family could claim
  m.emplace_back("shaft frequency from the spectrum (Hz)",
                 d.shaft_estimated
                     ? format_number(d.shaft_hz_estimated, 8) + " (" +
                           format_number(100 * (d.shaft_hz_estimated / o.fr - 1), 3) +
                           " % from the stated one, from the " + d.shaft_source +
                           (std::fabs(d.shaft_hz_estimated / o.fr - 1) > o.speed_refine
                                ? ", beyond --speed-refine: not used"
                                : "") +
                           "; " +
                           std::to_string(d.shaft_lines_masked) + " shaft and mains lines masked)"
                     : "no shaft comb stands out (" + std::to_string(d.shaft_lines_masked) +
                           " shaft and mains lines masked)");
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
  if (other_channel)
    m.emplace_back("other channel", other_channel->name + " (the other bearing's sensor)");
  if (across)
    m.emplace_back("second axis",
                   across->name + " (the sensor's axis at +90 deg from the record's)");
  if (o.baseline)
    m.emplace_back("baseline", a.get("--baseline") + " (at " + format_number(o.baseline->rate, 10) +
                                   " Hz, the record's rate)");
  if (std::isfinite(d.band_kurtosis))  // is the best band more than noise?
    m.emplace_back("band kurtosis significant",
                   std::string(d.band_kurtosis_significant() ? "yes" : "no") + " (Gaussian-noise " +
                       "threshold " + format_number(d.band_kurtosis_threshold, 4) +
                       " at alpha 0.01 over the bands searched)");
  Result r;
  r.meta = std::move(m);
  const DiagnosisContext ctx{o, in_orders, meta.defect, numerical_floor(s, meta), speed_source};
  r.json = size_only ? location_json(d, ctx, r.meta) : diagnosis_json(d, ctx, r.meta);
  r.table = size_only ? location_row(d) : diagnosis_row(d);
  r.text = size_only ? location_text(d, ctx) : diagnosis_text(d, ctx);
  out.write(r);
  return 0;
}

}  // namespace

int run_diagnose(const std::vector<std::string> &argv)
{
  return run_located(argv, false);
}

int run_size(const std::vector<std::string> &argv)
{
  return run_located(argv, true);
}

}  // namespace ohmdem::post::cli
