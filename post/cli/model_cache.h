// SPDX-License-Identifier: GPL-2.0-or-later
// The model data made of a record's scene (ohmdem-post model) and where it is cached: the
// scene's values (run.json's bearing geometry, speed, load, current, pit depth, sliding phase;
// the chain the record's acquire header states; the defect and the bank's sizes) in one
// canonical text, its hash the cache key (never a name).
#ifndef OHMDEM_POST_CLI_MODEL_CACHE_H
#define OHMDEM_POST_CLI_MODEL_CACHE_H

#include <string>
#include <vector>

#include "io/run_metadata.h"

namespace ohmdem::post::cli {

struct Scene {
  std::string text;          // "name = value" lines, sorted: what the key is made of
  std::string key;           // 16 hex digits of its 64-bit FNV-1a hash
  // The engine's and acquire's arguments, one word each (they reach no shell): "-var NAME
  // VALUE ..." (the defect and its size apart) and "--scale ... --rate ...".
  std::vector<std::string> deck_args;
  std::vector<std::string> acquire_args;
  std::string rate;          // the record's sampling rate (Hz), as its header states it
};

// Throws Error naming what the record's header or run.json lacks.
// `held_out`: the runs at sizes between the bank's that measure its own error (part of the key).
Scene record_scene(const std::string &record, const RunMetadata &meta, const std::string &defect,
                   const std::vector<double> &sizes, double length, int held_out);

// $OHMDEM_CACHE, else $XDG_CACHE_HOME/ohmdem, else $HOME/.cache/ohmdem; the folder is made.
std::string cache_dir();
std::string cached_bank_path(const Scene &s);  // <cache>/banks/bank_<key>.txt

// The bank's file, renamed onto `path` when whole: its header states the scene, its rows are
// `rows` (studies/template_bank.py's form); `model_error` the relative RMS error of the sizes
// the bank gave its held-out runs, `coverage` what they showed ("not measured ..." without).
void write_bank_file(const std::string &path, const Scene &s, const std::string &lowpass,
                     const std::string &bin, const std::string &rows, double model_error,
                     const std::string &coverage);

// The bank's sizes and run length when none are given (ohmdem-post model's defaults): 14 sizes
// from 0.2 to 3.64 deg, 25 % apart, 0.3 s after the sliding phase.
const std::vector<double> &default_bank_sizes();
constexpr double kDefaultRunLength = 0.3;
// Held-out runs when none are given: enough for an RMS error of the bank's sizes, few enough to
// add a fifth to the bank's cost.
constexpr int kDefaultHeldOut = 3;

std::string self_executable();  // /proc/self/exe
std::string find_engine();      // ohmdem beside this executable, else on PATH; empty: none
std::string default_deck();     // the source tree's (or the installed) bearing deck

}  // namespace ohmdem::post::cli

#endif
