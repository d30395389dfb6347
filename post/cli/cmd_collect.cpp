// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post collect: the indicators of many run folders in one table, one row per run, with
// the swept parameters read from each run's own run.json.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>

#include "bearing/diagnose.h"
#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/stats.h"
#include "io/read_table.h"
#include "io/run_folders.h"
#include "report/collect_report.h"

namespace ohmdem::post::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const char *const kDutyColumn = "n_masked";

// run.json keys describing how a run ended, not what it simulated: the status column shows
// them instead of parameter columns
bool is_outcome_key(const std::string &k)
{
  return k == "status" || k == "time_reached";
}

// One run: metadata, window, indicators, duty and (optionally) the diagnosis.
CollectedRun analyse(const Args &a, const std::string &run, bool want_diagnosis,
                     std::set<std::string> &nonscalar)
{
  CollectedRun r;
  r.run = run;
  const std::string signal = run_signal_file(run), json = run + "/run.json";
  std::vector<std::string> ns;
  r.params = run_parameters(json, &ns);
  r.params.erase(std::remove_if(r.params.begin(), r.params.end(),
                                [](const auto &kv) { return is_outcome_key(kv.first); }),
                 r.params.end());
  nonscalar.insert(ns.begin(), ns.end());
  const RunMetadata meta = read_run_metadata(json);
  r.status = meta.status.value_or("finished");

  InputOptions o;
  o.files = {signal};
  o.format = "table";
  o.column = a.get("--column");
  o.time_column = a.get("--time-column");
  o.resample = a.has("--resample");
  o.from = a.number("--from");
  o.to = a.number("--to");
  if (!a.has("--from") && !a.has("--keep-sliding") && meta.t_sliding_end)
    o.from = *meta.t_sliding_end;
  o.min_samples = want_diagnosis ? 256 : 2;
  const Signal s = load_named(o, meta);
  r.quantity = s.name;
  r.t_start = s.time(0);
  r.t_end = s.time(s.size() - 1);
  r.ind = indicators(s.x);

  // duty: the count column over the same window (same grid), when the run writes it
  TableOptions header;
  header.header_only = true;
  if (read_table(signal, header).find_name(kDutyColumn) != ColumnTable::npos) {
    InputOptions od = o;
    od.column = kDutyColumn;
    od.min_samples = 2;
    r.duty = duty_fraction(load_named(od, meta).x);
    r.has_duty = true;
  }

  if (want_diagnosis) {
    const BearingChoice bc = bearing_choice(a, meta);
    if (!bc.geometry)
      throw Error("--diagnose needs the bearing (run.json \"bearing\" or nb/db/dp, or --bearing)");
    if (!bc.fr)
      throw Error("--diagnose needs the shaft speed (run.json \"omega_inner\", or --rpm/--omega)");
    DiagnoseOptions d;
    d.geometry = *bc.geometry;
    d.fr = *bc.fr;
    r.diagnosis = diagnose(s, d);
  }
  return r;
}

std::string join(const std::vector<std::string> &v, const std::string &sep)
{
  std::string s;
  for (const auto &x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// The options of collect (run_collect parses them).
void declare_options(Args &a)
{
  a.section("Runs");
  a.flag("--recursive", "search the folders given and their subfolders for runs");
  a.flag("--skip-bad",
         "skip a run whose data are bad (empty, NaN, too short, bad run.json...) or that did "
         "not finish (run.json status interrupted or failed) with a warning instead of failing "
         "or including it");
  a.option("--params", "KEY[,KEY]", "only these run.json keys, in this order (default: all)");
  a.flag("--varying", "only the run.json keys whose value differs between the runs");
  a.section("Signal and window");
  a.option("--column", "NAME|N", "signal column of signal.txt", "R");
  a.option("--time-column", "NAME|N", "time column (default: time, t, TimeStep or Step)");
  a.flag("--resample", "interpolate non-uniform time stamps linearly (default: refuse them)");
  a.option("--from", "S", "start of the window for every run (default: t_sliding_end of run.json)");
  a.option("--to", "S", "end of the window (s) (default: the end of the data)");
  a.flag("--keep-sliding", "without --from, start at the beginning of the data");
  a.section("Diagnosis");
  a.flag("--diagnose",
         "add the columns diag_defect, diag_score, diag_frequency_Hz, diag_size_deg (as "
         "`diagnose` with its default options; bearing and speed from each run.json unless "
         "given below)");
  add_bearing_options(a);
  add_output_options(a);
}

// What the runs gave: a row each, the runs skipped as bad, the non-scalar run.json keys left
// out, how many did not finish.
struct Gathered {
  std::vector<CollectedRun> results;
  std::vector<std::string> bad;
  std::set<std::string> nonscalar;
  std::size_t unfinished = 0;
};

Gathered gather(const Args &a, const RunFolders &folders, bool skip_bad, bool want_diagnosis)
{
  Gathered g;
  std::vector<CollectedRun> &results = g.results;
  std::vector<std::string> &bad = g.bad;
  std::set<std::string> &nonscalar = g.nonscalar;
  std::size_t &unfinished = g.unfinished;
  for (const std::string &run : folders.runs) {
    try {
      const RunMetadata meta = read_run_metadata(run + "/run.json");
      if (!meta.finished()) {
        const std::string what =
            "did not finish (run.json status \"" + *meta.status + "\"" +
            (meta.time_reached ? ", time reached " + format_number(*meta.time_reached) + " s"
                               : std::string()) +
            ")";
        if (skip_bad) {
          std::cerr << "WARNING: collect: skipped run " << run << ": " << what << "\n";
          bad.push_back(run);
          continue;
        }
        std::cerr << "WARNING: collect: run " << run << " " << what
                  << "; its row covers the data written until then (column status; "
                     "--skip-bad skips such runs)\n";
        ++unfinished;
      }
      CollectedRun r = analyse(a, run, want_diagnosis, nonscalar);
      if (!results.empty() && r.quantity != results.front().quantity)
        throw Error("the signal is column '" + r.quantity + "', '" + results.front().quantity +
                    "' in " + results.front().run + "; choose one with --column");
      results.push_back(std::move(r));
    } catch (const Error &e) {
      if (!skip_bad)
        throw Error("run " + run + ": " + user_message(e) + " (--skip-bad skips such runs)");
      std::cerr << "WARNING: collect: skipped run " << run << ": " << user_message(e) << "\n";
      bad.push_back(run);
    }
  }
  if (results.empty())
    throw Error("collect: none of the " + std::to_string(folders.runs.size()) +
                " run(s) has usable data (all skipped by --skip-bad)");
  return g;
}

// The parameter columns: --params, else the run.json keys (--varying: those that differ).
std::vector<std::string> parameter_columns(const Args &a, const std::vector<CollectedRun> &results)
{
  std::vector<std::string> keys;
  if (a.has("--params")) {
    keys = split_commas(a.get("--params"));
    for (const auto &k : keys)
      if (std::none_of(results.begin(), results.end(), [&](const CollectedRun &r) {
            return find_parameter(r.params, k) != nullptr;
          }))
        throw Error("option --params: no run.json of the runs has the key '" + k + "'");
  } else {
    std::vector<const RunParameters *> params;
    for (const auto &r : results) params.push_back(&r.params);
    keys = parameter_keys(params, a.has("--varying"));
  }
  return keys;
}

// The '#' lines of the table: what was collected, skipped, and how.
MetaList collect_meta(const Args &a, const std::vector<std::string> &given, bool recursive,
                      const RunFolders &folders, const Gathered &g, const std::string &quantity,
                      const std::string &unit, bool any_duty, bool want_diagnosis)
{
  MetaList m;
  const std::vector<CollectedRun> &results = g.results;
  const std::vector<std::string> &bad = g.bad;
  const std::set<std::string> &nonscalar = g.nonscalar;
  const std::size_t unfinished = g.unfinished;
  m.emplace_back("runs", std::to_string(results.size()) + " collected from " + join(given, " ") +
                             (recursive ? " (recursive)" : ""));
  if (!folders.skipped.empty()) {
    std::vector<std::string> names;
    for (const auto &sk : folders.skipped) names.push_back(sk.first + " (" + sk.second + ")");
    m.emplace_back("folders skipped",
                   std::to_string(folders.skipped.size()) + ": " + join(names, "; "));
  }
  if (!bad.empty())
    m.emplace_back("bad runs skipped", std::to_string(bad.size()) + ": " + join(bad, " "));
  m.emplace_back("status",
                 "how each run ended (run.json \"status\"; a run.json without it, from an older "
                 "engine, counts as finished)" +
                     (unfinished ? "; " + std::to_string(unfinished) + " run(s) did not finish"
                                 : std::string()));
  m.emplace_back("parameters", a.has("--params") ? "--params " + a.get("--params")
                               : a.has("--varying")
                                   ? "run.json keys whose value differs between the runs"
                                   : "every scalar run.json key; empty where a run lacks it");
  if (!nonscalar.empty())
    m.emplace_back("non-scalar run.json keys left out",
                   join(std::vector<std::string>(nonscalar.begin(), nonscalar.end()), " "));
  m.emplace_back("signal", quantity + (unit.empty() ? "" : " (" + unit + ")"));
  std::string window =
      a.has("--from") ? "from " + a.get("--from") + " s (--from)"
      : a.has("--keep-sliding")
          ? "from the start of the data"
          : "from t_sliding_end of each run.json (the start of the data without it)";
  window += a.has("--to") ? " to " + a.get("--to") + " s" : " to the end of the data";
  m.emplace_back("window", window);
  m.emplace_back("kurtosis", "Pearson (normal law = 3)");
  if (any_duty)
    m.emplace_back("duty", std::string("fraction of the window's samples with ") + kDutyColumn +
                               " >= 1 (empty where a run has no " + kDutyColumn + " column)");
  if (want_diagnosis)
    m.emplace_back("diagnosis", "as ohmdem-post diagnose with its default options, same window");
  return m;
}

// The run folders in `given`; none is an error naming the reasons, the folders skipped are
// warnings.
RunFolders runs_in(const std::vector<std::string> &given, bool recursive)
{
  RunFolders folders = find_run_folders(given, recursive);
  for (auto &sk : folders.skipped) sk.second = flag_named(sk.second);  // "{runs.recursive}"
  if (folders.runs.empty()) {  // one error line, with the reasons, instead of the warnings
    std::string why;
    for (std::size_t k = 0; k < folders.skipped.size() && k < 4; ++k)
      why += "; " + folders.skipped[k].first + ": " + folders.skipped[k].second;
    if (folders.skipped.size() > 4)
      why += "; and " + std::to_string(folders.skipped.size() - 4) + " more";
    throw Error("collect: no run folder (a folder holding signal.txt and run.json) in " +
                join(given, " ") + (recursive ? "" : " (try --recursive)") + ", " +
                std::to_string(folders.skipped.size()) + " skipped" + why);
  }
  for (const auto &sk : folders.skipped)
    std::cerr << "WARNING: collect: skipped " << sk.first << ": " << sk.second << "\n";
  return folders;
}

}  // namespace

int run_collect(const std::vector<std::string> &argv)
{
  Args a("collect", "[options] DIR...",
         "Gathers the runs found in the folders given (a run is a folder holding signal.txt and\n"
         "run.json) into one table: one row per run, sorted by folder (natural order), with the\n"
         "folder, the swept parameters (every scalar key of the runs' run.json, sorted; empty\n"
         "where a run lacks one), the analysis window, the indicators of `stats` over it, the\n"
         "duty (fraction of samples with n_masked >= 1) and, with --diagnose, the diagnosis.\n"
         "The window starts at t_sliding_end of each run.json unless --from or --keep-sliding.");
  declare_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  if (a.positional().empty())
    throw Error("collect: no folder given (see ohmdem-post collect --help)");
  if (a.has("--params") && a.has("--varying"))
    throw Error("collect: give --params or --varying, not both");
  const bool recursive = a.has("--recursive"), skip_bad = a.has("--skip-bad"),
             want_diagnosis = a.has("--diagnose");
  // options that apply to every run fail here, not as the first run's error
  (void)parse_output_format(a.get("--format"));
  const double from = a.number("--from"), to = a.number("--to");
  if (std::isfinite(from) && std::isfinite(to) && !(to > from))
    throw Error("--to (" + a.get("--to") + " s) must be after --from (" + a.get("--from") + " s)");
  if (want_diagnosis) (void)bearing_choice(a, RunMetadata{});

  std::vector<std::string> given = a.positional();  // sorted for messages: order-independent
  std::sort(given.begin(), given.end(), natural_less);
  const RunFolders folders = runs_in(given, recursive);

  const Gathered g = gather(a, folders, skip_bad, want_diagnosis);
  const std::vector<CollectedRun> &results = g.results;
  const std::vector<std::string> keys = parameter_columns(a, results);
  const std::string quantity = results.front().quantity;
  const std::string unit = unit_of(a, quantity);
  const bool any_duty =
      std::any_of(results.begin(), results.end(), [](const CollectedRun &r) { return r.has_duty; });
  Result rep;
  rep.table = collected_table(results, keys, unit, want_diagnosis);

  rep.meta =
      collect_meta(a, given, recursive, folders, g, quantity, unit, any_duty, want_diagnosis);
  std::vector<std::string> read;  // the runs' files: --output must be none of them
  for (const std::string &run : folders.runs) {
    for (const char *f : {"/signal.txt", "/signal.npy", "/run.json"}) read.push_back(run + f);
  }
  Output out(a, read);
  out.write(rep);
  return 0;
}

}  // namespace ohmdem::post::cli
