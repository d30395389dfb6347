// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/common.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>

#include "core/constants.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "io/read_log.h"
#include "io/read_mat.h"

namespace ohmdem::post::cli {

void add_input_options(Args &a, const std::string &rate_option)
{
  a.section("Input");
  a.option("--input", "KIND",
           "input format: auto|table|log|dump|mat|npy (auto: .mat files are MAT, files "
           "starting with the .npy magic NumPy)",
           "auto");
  a.option("--column", "NAME|N",
           "signal column: header name (R, c_x[2], f_ID[1], v_name) or 1-based number; "
           "default: the only non-time column, else R");
  a.option("--time-column", "NAME|N",
           "time column (seconds; TimeStep/Step count steps, see --dt); 'none' to use " +
               rate_option + "; default: time, t, TimeStep or Step");
  a.option(rate_option, "HZ", "sampling rate of a signal without time stamps (overrides any time)");
  a.option("--variable", "NAME", "MAT files: the signal variable (e.g. DE_time); as --column");
  a.option("--rate-variable", "NAME", "MAT files: the variable holding the sampling rate (Hz)");
  a.option("--dt", "S", "time step length for step-stamped data (dumps, logs, fix ave/time)");
  a.option("--log", "FILE",
           "take the time step length from this LIGGGHTS log (its last "
           "'timestep' command)");
  a.option("--aggregate", "HOW", "dumps: reduce the rows of a frame: sum|mean|min|max|rms|count",
           "mean");
  a.flag("--resample", "interpolate non-uniform time stamps linearly (default: refuse them)");
  a.option("--from", "S", "start of the analysis window (s, same clock as the file)");
  a.option("--to", "S", "end of the analysis window (s)");
  a.option("--metadata", "FILE", "run metadata (JSON); default: run.json next to the input");
  a.flag("--no-metadata", "ignore run.json next to the input");
}

InputOptions input_options(const Args &a, const std::string &rate_option)
{
  InputOptions o;
  o.files = a.positional();
  if (o.files.empty())
    throw Error(a.command() + ": no input file (see ohmdem-post " + a.command() + " --help)");
  o.format = a.get("--input");
  o.column = a.get("--column");
  if (a.has("--variable")) {
    if (a.has("--column")) throw Error("give the signal once: --column or --variable");
    o.column = a.get("--variable");
  }
  o.rate_variable = a.get("--rate-variable");
  o.time_column = a.get("--time-column");
  o.rate = a.has(rate_option) ? a.number_in(rate_option, 0, Range::above(0), "a rate", "Hz") : 0;
  o.dt = a.has("--dt") ? a.number_in("--dt", 0, Range::above(0), "a step", "s") : 0;
  if (a.has("--log")) {
    if (a.has("--dt")) throw Error("give the step length once: --dt or --log");
    if (a.get("--log") == "-" && std::find(o.files.begin(), o.files.end(), "-") != o.files.end())
      throw Error("standard input ('-') can be read only once: give --log a file");
    o.dt = log_timestep(a.get("--log"));
  }
  o.aggregate = parse_aggregate(a.get("--aggregate"));
  o.resample = a.has("--resample");
  o.from = a.number("--from");
  o.to = a.number("--to");
  return o;
}

RunMetadata run_metadata(const Args &a)
{
  if (a.has("--metadata")) return read_run_metadata(a.get("--metadata"));
  if (a.has("--no-metadata") || a.positional().empty()) return {};
  const std::string p = find_run_metadata(a.positional().front());
  return p.empty() ? RunMetadata{} : read_run_metadata(p);
}

Signal load_named(const InputOptions &o, const RunMetadata &meta, const std::string &rate_option)
{
  SettingFlags flags;
  if (rate_option != "--rate")
    flags = {{"input.rate", rate_option}, {"input.rate_variable", rate_option + "-variable"}};
  Signal s;
  try {
    s = load_signal(o, meta);
  } catch (const SettingError &e) {
    throw Error(flag_named(e.text(), flags));
  }
  for (auto &kv : s.meta)
    if (kv.first == "time base") kv.second = flag_named(kv.second, flags);
  return s;
}

Signal load_companion(const InputOptions &io, const RunMetadata &meta, const Signal &s,
                      const CompanionNames &n, const std::string &rate_option)
{
  Signal o = load_named(io, meta, rate_option);
  if (std::fabs(o.rate / s.rate - 1) > 1e-9 || o.x.size() != s.x.size())
    throw Error(n.command + ": " + n.what + " holds " + std::to_string(o.x.size()) +
                " samples at " + format_number(o.rate, 10) + " Hz, the " + n.record + " " +
                std::to_string(s.x.size()) + " at " + format_number(s.rate, 10) +
                " Hz: the two channels must be recorded together (same rate and samples)");
  if (o.x == s.x)
    throw Error(n.command + ": " + n.what + " holds the " + n.record +
                "'s own samples: " + n.name_it);
  return o;
}

Signal load_input(const Args &a, const RunMetadata &meta, std::size_t min_samples,
                  bool skip_sliding_phase, const std::string &rate_option)
{
  InputOptions o = input_options(a, rate_option);
  o.min_samples = min_samples;
  bool auto_from = false;
  if (skip_sliding_phase && !a.has("--from") && meta.t_sliding_end) {
    o.from = *meta.t_sliding_end;
    auto_from = true;
  }
  Signal s = load_named(o, meta, rate_option);
  if (meta.present()) s.meta.emplace_back("metadata", meta.path);
  if (auto_from)
    s.meta.emplace_back("sliding phase skipped", "t < " + format_number(o.from) + " s");
  return s;
}

void add_output_options(Args &a)
{
  a.section("Output");
  a.option("--format", "FMT", "table|csv|json", "table");
  a.option("--output", "FILE", "write to FILE instead of standard output");
  a.option("--unit", "UNIT", "unit of the signal, for column names (default: ohm for R)");
}

std::vector<std::string> input_files(const Args &a, const std::string &output,
                                     const std::vector<std::string> &more)
{
  std::vector<std::string> files = a.positional();
  const std::vector<std::string> values = a.given_values(output);
  files.insert(files.end(), values.begin(), values.end());
  if (!a.positional().empty()) files.push_back(find_run_metadata(a.positional().front()));
  files.insert(files.end(), more.begin(), more.end());
  return files;
}

void refuse_input_as_output(const std::string &option, const std::string &output,
                            const std::vector<std::string> &inputs)
{
  struct stat out {};
  if (::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) return;  // a new file
  for (const std::string &in : inputs) {
    struct stat st {};
    if (in.empty() || in == "-" || ::stat(in.c_str(), &st) != 0) continue;
    if (st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      throw Error("option " + option + " " + output + " is one of the inputs (" + in +
                  (in == output ? "" : ", the same file") +
                  "): writing it would destroy what is read; give another file");
  }
}

Output::Output(const Args &a, const std::vector<std::string> &more_inputs)
    : out_(&std::cout),
      format_(parse_output_format(a.get("--format"))),
      unwinding_(std::uncaught_exceptions())
{
  if (a.has("--output")) {
    path_ = a.get("--output");
    refuse_input_as_output("--output", path_, input_files(a, "--output", more_inputs));
    file_ = std::make_unique<PendingStream>(path_);
  }
}

Output::~Output()
{
  if (!file_) return;
  // a command that failed (an exception leaves through here) writes nothing: the error is its
  if (std::uncaught_exceptions() > unwinding_) return;
  const std::string why = file_->finish();
  if (why.empty()) return;
  const PendingFile &f = file_->file();
  failed_outputs().push_back("writing '" + path_ + "' failed: " + why + "; " +
                             (f.in_place()   ? "the output is lost or cut"
                              : f.replaces() ? "the file is left as it was"
                                             : "no file is left"));
}

std::vector<std::string> &failed_outputs()
{
  static std::vector<std::string> failed;
  return failed;
}

void add_bearing_options(Args &a)
{
  a.section("Bearing and speed");
  a.option("--bearing", "NAME",
           "a bearing of the catalog (inputs/bearings, e.g. machado2014 the paper's, "
           "6205-2RS_JEM CWRU's drive end)");
  a.option("--catalog", "DIR",
           "bearing catalog folder (default: $OHMDEM_CATALOG, else the installed "
           "share/ohmdem/inputs/bearings, else the source tree's inputs/bearings)");
  a.option("--nb", "N", "number of balls");
  a.option("--db", "M", "ball diameter (m)");
  a.option("--dp", "M", "pitch diameter (m)");
  a.option("--beta", "DEG", "contact angle (degrees)");
  a.option("--contact-angle", "DEG",
           "contact angle (degrees), as --beta; default: run.json's (a model 3d run's measured "
           "mean)");
  a.option("--factors", "LIST",
           "BPFO,BPFI,BSF,FTF (or BPFO,BPFI): the maker's defect frequencies as multiples of "
           "the shaft frequency, for a bearing in no catalog (they win over the geometry)");
  // one speed option per unit
  a.option("--rpm", "RPM", "shaft speed (rev/min)");
  a.option("--shaft-hz", "HZ", "shaft frequency (Hz)");
  a.option("--omega", "RAD/S", "shaft angular speed (rad/s), as omega_inner in our decks");
  a.retired("--fr", "give the shaft frequency in Hz with --shaft-hz (or --rpm, --omega)");
  a.option("--rpm-variable", "NAME", "MAT files: the variable holding the shaft speed (rpm)");
}

BearingChoice bearing_choice(const Args &a, const RunMetadata &meta)
{
  BearingChoice c;
  BearingGeometry g;
  bool have = false;
  const std::string catalog = a.has("--catalog") ? a.get("--catalog") : default_catalog_dir();
  const bool completed = a.has("--nb") || a.has("--db") || a.has("--dp") || a.has("--factors");
  if (a.has("--bearing")) {
    const CatalogEntry e = catalog_entry(catalog, a.get("--bearing"));
    g = completed ? e.partial() : e.geometry();  // --dp may complete an entry without one
    have = true;
    c.geometry_source = e.path;
  } else if (meta.bearing && *meta.bearing != "custom" && !(meta.nb && meta.db && meta.dp)) {
    // an older run.json that names its bearing only
    const CatalogEntry e = catalog_entry(catalog, *meta.bearing);
    g = e.geometry();
    have = true;
    c.geometry_source = meta.path + " (" + e.path + ")";
  } else if (meta.nb && meta.db && meta.dp) {
    g.name = meta.bearing ? *meta.bearing : "custom";
    g.nb = static_cast<int>(std::lround(*meta.nb));
    g.db = *meta.db;
    g.dp = *meta.dp;
    g.contact_angle_deg = meta.contact_angle.value_or(0);
    have = true;
    c.geometry_source = meta.path;
  }
  if (a.has("--beta") && a.has("--contact-angle"))
    throw Error("give the contact angle once: --beta or --contact-angle, not both");
  const char *angle = a.has("--contact-angle") ? "--contact-angle" : "--beta";
  const bool explicit_geom = a.has("--nb") || a.has("--db") || a.has("--dp") || a.has(angle);
  if (explicit_geom) {
    if (!have && !(a.has("--nb") && a.has("--db") && a.has("--dp")))
      throw Error(
          "explicit geometry needs --nb, --db and --dp (and optionally --beta), or a "
          "--bearing preset to modify");
    if (!have) g.name = "custom";
    if (a.has("--nb")) {
      g.nb = static_cast<int>(a.integer_in("--nb", 0, 1, 1000, "a ball count"));
    }
    if (a.has("--db")) g.db = a.number("--db");
    if (a.has("--dp")) g.dp = a.number("--dp");
    if (a.has(angle)) g.contact_angle_deg = a.number(angle);
    if (have) g.name += " (modified)";
    have = true;
    c.geometry_source = "command line";
  }
  if (a.has("--factors")) {
    g.factors = parse_factors(a.get("--factors"));
    if (!have) g.name = "factors";
    if (g.nb == 0) g.nb = static_cast<int>(std::lround(g.factors->bpfo + g.factors->bpfi));
    if (have && g.name.find(" (modified)") == std::string::npos) g.name += " (modified)";
    have = true;
    c.geometry_source = "command line";
  }
  if (have) {
    validate(g);
    c.geometry = g;
  }
  int speeds = a.has("--rpm") + a.has("--shaft-hz") + a.has("--omega") + a.has("--rpm-variable");
  if (speeds > 1)
    throw Error("give the shaft speed once: --rpm, --shaft-hz, --omega or --rpm-variable");
  // the speed in the option's own unit, refused when not > 0 naming the option
  const auto speed = [&](const char *name, const char *unit) {
    return a.number_in(name, NAN, Range::above(0), "a shaft speed", unit);
  };
  double fr = NAN;
  if (a.has("--rpm")) fr = speed("--rpm", "rpm") / 60;
  if (a.has("--shaft-hz")) fr = speed("--shaft-hz", "Hz");
  if (a.has("--omega")) fr = speed("--omega", "rad/s") / (2 * kPi);
  if (a.has("--rpm-variable")) {
    if (a.positional().empty()) throw Error("option --rpm-variable needs a MAT input file");
    const std::string &mat = a.positional().front(), &name = a.get("--rpm-variable");
    const double rpm = read_mat_scalar(mat, name);
    if (!(rpm > 0))
      throw Error(mat + ": variable '" + name + "' (--rpm-variable) is " + format_number(rpm) +
                  "; a shaft speed must be > 0 rpm");
    fr = rpm / 60;
  }
  if (speeds) {
    c.fr = fr;
    c.fr_source = a.has("--rpm-variable") ? "MAT variable " + a.get("--rpm-variable") + " (rpm)"
                  : a.has("--rpm")        ? "command line --rpm"
                  : a.has("--shaft-hz")   ? "command line --shaft-hz"
                                          : "command line --omega";
  } else if (meta.omega_inner) {
    if (!(*meta.omega_inner > 0)) throw Error(meta.path + ": \"omega_inner\" must be > 0");
    c.fr = *meta.omega_inner / (2 * kPi);
    c.fr_source = meta.path;
  }
  return c;
}

int harmonics_option(const Args &a, long long fallback)
{
  return static_cast<int>(a.integer_in("--harmonics", fallback, 1, kMaxHarmonics));
}

int levels_option(const Args &a)
{
  return static_cast<int>(a.integer_in("--levels", 7, 0, 16));
}

std::size_t peaks_option(const Args &a)
{
  return static_cast<std::size_t>(a.integer_in("--peaks", 10, 0, 100000));
}

double tolerance_option(const Args &a)
{
  return a.number_in("--tolerance", 0.02, Range::open(0, 0.2), "a fraction");
}

Band band_option(const Args &a)
{
  const auto v = a.values("--band");
  const Band b{parse_option_double("--band", v.at(0)), parse_option_double("--band", v.at(1))};
  if (!(b.hi > b.lo) || b.lo < 0)
    throw Error("option --band expects 0 <= F1 < F2 (Hz), got " + v[0] + " " + v[1]);
  return b;
}

std::string unit_of(const Args &a, const std::string &q)
{
  if (a.has("--unit")) return a.get("--unit");
  if (q == "R" || q.rfind("R_", 0) == 0) return "ohm";
  if (q == "time" || q == "t") return "s";
  if (q.rfind("fn_", 0) == 0) return "N";
  if (q.rfind("omega", 0) == 0) return "rad/s";
  return "";
}

}  // namespace ohmdem::post::cli
