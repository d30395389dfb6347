// SPDX-License-Identifier: GPL-2.0-or-later
// Turns input files into one uniformly sampled Signal: detects the format (our signal.txt and
// other column files, LIGGGHTS logs, LIGGGHTS dumps, plain one-column signals), picks the value
// and time columns, converts time steps to seconds, checks uniform sampling, applies the window.
#ifndef OHMDEM_POST_LOAD_SIGNAL_H
#define OHMDEM_POST_LOAD_SIGNAL_H

#include <cmath>
#include <string>
#include <vector>

#include "core/sampled_signal.h"
#include "io/read_dump.h"
#include "io/run_metadata.h"

namespace ohmdem::post {

struct InputOptions {
  std::vector<std::string> files;
  std::string format = "auto";  // auto | table | log | dump | mat
  std::string column;           // name or 1-based number; empty = the obvious one
  std::string time_column;      // name or number; "none" = use `rate`; empty = auto
  double rate = 0;              // Hz, for signals without time stamps (overrides a time column)
  std::string rate_variable;    // MAT files: the variable holding the sampling rate (Hz)
  double dt = 0;                // s per time step, for step-stamped data (dumps, logs, ave/time)
  Aggregate aggregate = Aggregate::Mean;  // dumps: how the rows of a frame become one value
  bool resample = false;                  // interpolate non-uniform time stamps instead of refusing
  double from = NAN, to = NAN;            // time window (s)
  std::size_t min_samples = 2;
};

// `meta` may supply dt when the options do not.
Signal load_signal(const InputOptions &opt, const RunMetadata &meta);

}  // namespace ohmdem::post

#endif
