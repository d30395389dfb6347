// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post model: the model data a size method needs (a bank of pulse templates), made of
// the record's own scene (its run.json and the header acquire wrote) by running the engine
// `ohmdem` at known sizes, each run passed through the record's chain and folded, cached under
// the user's cache folder keyed by the scene's values (cli/model_cache.h).
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "cli/commands.h"
#include "cli/common.h"
#include "cli/model_cache.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "io/json.h"

extern char **environ;  // POSIX: the process environment, passed to the engine runs

namespace ohmdem::post::cli {

namespace {

// Runs `argv` (argv[0] a path, or a name looked up on PATH) with its standard output and error
// into `log`, no shell between: the words come from run.json and the record's header. True when
// it exits 0.
bool run_program(const std::vector<std::string> &argv, const std::string &log)
{
  std::vector<char *> args;
  for (const std::string &w : argv) args.push_back(const_cast<char *>(w.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t io;
  posix_spawn_file_actions_init(&io);
  posix_spawn_file_actions_addopen(&io, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&io, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &io, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&io);
  if (rc != 0) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string> &b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The fold's lines 'Y SE' of diagnose --pulse-fold-out, and its empty bins.
bool read_fold(const std::string &path, std::vector<std::string> &y, std::vector<std::string> &se,
               std::string &lowpass, std::string &bin, int &empty)
{
  std::ifstream in(path);
  std::string line;
  empty = -1;
  while (std::getline(in, line)) {
    if (line.rfind("# lowpass: ", 0) == 0) lowpass = line.substr(11);
    if (line.rfind("# bin (s): ", 0) == 0) bin = line.substr(11);
    if (line.rfind("# bins no pass fell in: ", 0) == 0) empty = std::atoi(line.c_str() + 24);
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string a, b;
    if (!(ls >> a >> b)) return false;
    y.push_back(a);
    se.push_back(b);
  }
  return y.size() >= 8 && empty >= 0;
}

// Sizes between the bank's (geometric midpoints of neighbours), n of them spread over its range.
std::vector<double> held_out_sizes(const std::vector<double> &sizes, int n)
{
  std::vector<double> out;
  const std::size_t gaps = sizes.size() - 1;
  for (int j = 0; j < n; ++j) {
    const std::size_t i =
        n == 1 ? gaps / 2
               : static_cast<std::size_t>(std::lround(static_cast<double>(j) *
                                                      static_cast<double>(gaps - 1) / (n - 1)));
    const double m = std::sqrt(sizes[i] * sizes[i + 1]);
    if (out.empty() || m > out.back()) out.push_back(m);
  }
  return out;
}

// acquire's arguments with the noise seed moved by `by` (none to move without noise)
std::vector<std::string> reseeded(std::vector<std::string> args, std::size_t by)
{
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--seed")
      args[i + 1] = std::to_string(std::atol(args[i + 1].c_str()) + static_cast<long>(by));
  return args;
}

struct HeldOut {
  int sized = 0, covered = 0;
  double rms = 0;     // relative RMS error of the sizes given
  std::string sizes;  // "TRUE->GIVEN [LO, HI]" per run
};

// The held-out records (work/hJ.V.txt) sized by `bank` as the user's record would be.
HeldOut size_held_out(const std::string &self, const std::string &work, const std::string &bank,
                      const std::string &defect, const std::vector<double> &held,
                      const std::vector<int> &ok, std::size_t first)
{
  HeldOut h;
  double sum2 = 0;
  for (std::size_t j = 0; j < held.size(); ++j) {
    const std::string run = work + "/h" + std::to_string(j);
    std::string given = "-";
    if (ok[first + j] &&
        run_program({self, "size", run + ".V.txt", "--metadata", run + "/run.json", "--model", bank,
                     "--assume-defect", defect, "--format", "json", "--output", run + ".size.json"},
                    run + ".size.log")) {
      std::ifstream in(run + ".size.json");
      std::stringstream text;
      text << in.rdbuf();
      try {
        const Json r = Json::parse(text.str(), run + ".size.json");
        const Json *v = r.find("size_deg");
        const Json *iv = r.find("size_interval_deg");
        if (v && v->is_number()) {
          const double e = v->number() / held[j] - 1;
          sum2 += e * e;
          ++h.sized;
          given = format_number(v->number(), 3);
          if (iv && iv->is_array() && iv->size() == 2 && (*iv)[0].is_number() &&
              (*iv)[1].is_number()) {
            given += " [" + format_number((*iv)[0].number(), 3) + ", " +
                     format_number((*iv)[1].number(), 3) + "]";
            if ((*iv)[0].number() <= held[j] && held[j] <= (*iv)[1].number()) ++h.covered;
          }
        }
      } catch (const Error &) {
        given = "-";
      }
    }
    h.sizes += (h.sizes.empty() ? "" : ", ") + format_number(held[j], 3) + " -> " + given;
  }
  if (h.sized > 0) h.rms = std::sqrt(sum2 / h.sized);
  return h;
}

}  // namespace

int run_model(const std::vector<std::string> &argv)
{
  Args a("model", "[options] RECORD",
         "The model data of the record's scene for the template size method: a bank of the\n"
         "pulse folds of simulations of the same scene (run.json's bearing by its values, speed,\n"
         "load, current, pit depth) at known sizes, each passed through the record's own chain\n"
         "(the header acquire wrote: scale, offset, anti-alias filter, rate, noise, ADC) and\n"
         "folded at the defect's period. It runs the engine ohmdem (beside ohmdem-post, else on\n"
         "PATH), --jobs at a time, with a progress line, and caches the bank under\n"
         "$OHMDEM_CACHE, else $XDG_CACHE_HOME/ohmdem, else ~/.cache/ohmdem, keyed by the scene's\n"
         "values (never a name); diagnose and size reuse it with no option. Its own error is\n"
         "measured on --held-out runs at sizes between the bank's (another noise draw): their\n"
         "sizes' relative RMS error widens every interval the bank gives, and the bank states\n"
         "how many of their intervals held the truth; with --held-out 0 it gives no interval.\n"
         "Example: ohmdem-post model results/pit/V.txt --defect inner");
  add_input_options(a);
  a.section("Model");
  a.option("--defect", "KIND", "the race defect the bank is of: inner or outer", "inner");
  a.option("--sizes", "LIST", "the bank's sizes (deg, comma-separated, increasing; default: 14 "
           "from 0.2 to 3.64 deg, 25 % apart)");
  a.option("--held-out", "N", "runs at sizes between the bank's that measure its error (0..8)",
           "3");
  a.option("--jobs", "N", "engine runs at a time (1..64)", "2");
  a.option("--length", "S", "simulated time after the sliding phase of each run (s)", "0.3");
  a.option("--engine", "FILE", "the engine (default: ohmdem beside ohmdem-post, else on PATH)");
  a.option("--deck", "FILE", "the bearing deck (default: the source tree's inputs/bearing_6208/in.bearing)");
  a.flag("--print-key", "print the scene's key and the cache file, make nothing");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const auto files = input_options(a).files;
  if (files.size() != 1) throw Error("model: give one RECORD (an acquired record with its header)");
  const RunMetadata meta = run_metadata(a);
  const std::string defect = a.get("--defect");
  if (defect != "inner" && defect != "outer")
    throw Error("model: --defect must be inner or outer, got '" + defect + "'");
  std::vector<double> sizes;
  if (!a.has("--sizes")) sizes = default_bank_sizes();
  for (const std::string &t : a.has("--sizes") ? split_commas(a.get("--sizes"))
                                               : std::vector<std::string>{}) {
    double v = 0;
    if (!parse_double(t, v) || !(v > 0 && v < 90) || (!sizes.empty() && v <= sizes.back()))
      throw Error("model: --sizes expects increasing sizes in (0, 90) deg, comma-separated, got '" +
                  a.get("--sizes") + "'");
    sizes.push_back(v);
  }
  if (sizes.size() < 3) throw Error("model: --sizes needs at least 3 sizes");
  const int jobs = static_cast<int>(a.integer_in("--jobs", 2, 1, 64, "a number of runs"));
  const double length =
      a.number_in("--length", kDefaultRunLength, Range::open(0.01, 100), "a duration", "s");
  const int n_held = static_cast<int>(
      a.integer_in("--held-out", kDefaultHeldOut, 0, 8, "a number of runs"));
  const std::vector<double> held = held_out_sizes(sizes, n_held);
  const Scene scene = record_scene(files[0], meta, defect, sizes, length, n_held);
  const std::string path = cached_bank_path(scene);
  if (a.has("--print-key")) {
    std::cout << scene.key << " " << path << "\n";
    return 0;
  }
  if (access(path.c_str(), R_OK) == 0) {
    std::cout << path << " (cached: the scene's bank exists)\n";
    return 0;
  }
  const std::string engine = a.has("--engine") ? a.get("--engine") : find_engine();
  if (engine.empty())
    throw Error(
        "model: no engine: ohmdem is neither beside ohmdem-post nor on PATH (a post-only "
        "build). Build the engine (README, Install) and rerun, give it with --engine FILE, or "
        "make the bank where an engine runs (studies/template_bank.py) and give it to size or "
        "diagnose with --model FILE");
  // a held-out run is as long as the record (at most --length): its scatter is the record's
  const double held_length =
      held.empty() ? length : std::min(length, load_input(a, meta, 256, true).duration());
  const std::vector<std::string> held_deck_args =
      held_length == length
          ? scene.deck_args
          : record_scene(files[0], meta, defect, sizes, held_length, n_held).deck_args;
  const std::string deck = a.has("--deck") ? a.get("--deck") : default_deck();
  const std::string deck_dir = deck.substr(0, deck.find_last_of('/'));
  const std::string work = path + ".work";
  std::error_code made;
  std::filesystem::create_directories(work, made);
  if (made) throw Error("model: cannot create the work folder " + work + ": " + made.message());
  const std::string self = self_executable();
  const std::size_t total = sizes.size() + held.size();
  std::vector<int> ok(total, 0);
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const auto t0 = std::chrono::steady_clock::now();
  auto worker = [&]() {
    for (std::size_t k = next++; k < total; k = next++) {
      const bool bank_run = k < sizes.size();
      const std::size_t j = bank_run ? k : k - sizes.size();
      const std::string run = work + (bank_run ? "/s" : "/h") + std::to_string(j);
      const double size = bank_run ? sizes[j] : held[j];
      const std::vector<std::string> sim = joined(
          {engine, "-in", deck, "-var", "here", deck_dir, "-var", "out", run, "-log", run + ".log",
           "-screen", "none"},
          joined(bank_run ? scene.deck_args : held_deck_args,
                 {"-var", "defect", defect, "-var", "size", format_number(size, 10)}));
      // a held-out run is a record as the user's: another draw of the chain's noise
      const std::vector<std::string> acq = joined(
          joined({self, "acquire", run + "/signal.txt", "--column", "R"},
                 bank_run ? scene.acquire_args : reseeded(scene.acquire_args, 2000 + j)),
          {"--name", "V", "--output", run + ".V.txt"});
      const std::vector<std::string> fold = {
          self, "diagnose", run + ".V.txt", "--metadata", run + "/run.json", "--no-size",
          "--format", "json", "--assume-defect", defect, "--pulse-fold-out", run + ".fold"};
      ok[k] = run_program(sim, run + ".stdout") && run_program(acq, run + ".acquire.log") &&
              (!bank_run || run_program(fold, run + ".diagnose.log"));
      // the run's signal (~70 MB at 1 MHz) is not kept: the fold is what the bank needs
      std::error_code gone;
      std::filesystem::remove(run + "/signal.txt", gone);
      const std::size_t n = ++done;
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::lock_guard<std::mutex> lock(print);
      std::cerr << "model: " << n << " of " << total << " runs, " << format_number(s, 3)
                << " s, about "
                << format_number(s / static_cast<double>(n) * static_cast<double>(total - n), 3)
                << " s left\n";
    }
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
  for (std::thread &t : pool) t.join();
  std::ostringstream rows;
  std::string lowpass, bin;
  std::size_t kept = 0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    std::vector<std::string> y, se;
    int empty = 0;
    const std::string run = work + "/s" + std::to_string(k);
    if (!ok[k] || !read_fold(run + ".fold", y, se, lowpass, bin, empty) || empty > 0) {
      std::cerr << "model: size " << sizes[k] << " deg left out (" << run
                << ".stdout and .log say why when the run failed; a fold with bins no pass "
                   "fell in needs a longer --length)\n";
      continue;
    }
    rows << format_number(sizes[k], 10) << " 0 " << y.size();
    for (const std::string &v : y) rows << ' ' << v;
    for (const std::string &v : se) rows << ' ' << v;
    rows << '\n';
    ++kept;
  }
  if (kept < 3)
    throw Error("model: fewer than 3 of the " + std::to_string(sizes.size()) +
                " runs gave a fold (their logs: " + work + "): no bank");
  double model_error = 0;
  std::string coverage = "not measured (no held-out runs)";
  if (!held.empty()) {
    // the bank's sizes of its held-out records: first without an error of its own, for the
    // error; then with it, for how many intervals hold the truth
    const std::string trial = work + "/bank_trial.txt";
    const std::string measuring = "being measured by ohmdem-post model";
    write_bank_file(trial, scene, lowpass, bin, rows.str(), 0, measuring);
    const HeldOut first = size_held_out(self, work, trial, defect, held, ok, sizes.size());
    if (first.sized >= 2) {
      model_error = std::min(0.99, first.rms);
      write_bank_file(trial, scene, lowpass, bin, rows.str(), model_error, measuring);
      const HeldOut second = size_held_out(self, work, trial, defect, held, ok, sizes.size());
      coverage = "its intervals held " + std::to_string(second.covered) + " of " +
                 std::to_string(held.size()) + " held-out runs of " +
                 format_number(held_length, 3) + " s (sizes " + second.sizes +
                 " deg; relative RMS error " + format_number(100 * first.rms, 3) + " %)";
    } else {
      coverage = "not measured (" + std::to_string(first.sized) + " of " +
                 std::to_string(held.size()) + " held-out runs sized)";
    }
    std::cerr << "model: held-out runs: " << coverage << "\n";
  }
  write_bank_file(path, scene, lowpass, bin, rows.str(), model_error, coverage);
  // the runs' logs are kept only when a size was left out (the messages above name them)
  if (kept == sizes.size()) {
    std::error_code gone;
    std::filesystem::remove_all(work, gone);
  }
  std::cout << path << "\n";
  return 0;
}

}  // namespace ohmdem::post::cli
