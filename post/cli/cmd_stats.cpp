// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post stats: the statistical indicators of the paper and more, over a window or per
// sliding window.
#include <cmath>
#include <iostream>

#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"
#include "dsp/stats.h"
#include "report/stats_report.h"

namespace ohmdem::post::cli {

int run_stats(const std::vector<std::string> &argv)
{
  Args a("stats", "[options] FILE...",
         "Statistical indicators of the signal over [--from, --to], or per sliding window.\n"
         "Moments are computed on the signal as given (the mean is not removed unless\n"
         "--remove-mean); kurtosis is Pearson's (3 for a normal law).");
  add_input_options(a);
  a.section("Indicators");
  a.option("--window-length", "S", "compute per sliding window of this length (s)");
  a.option("--step", "S", "hop between sliding windows (s) (default: the window length)");
  a.flag("--remove-mean", "subtract the mean of each window before computing");
  add_output_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const RunMetadata meta = run_metadata(a);
  Signal s = load_input(a, meta, 2);
  Output out(a);
  const std::string unit = unit_of(a, s.name);
  const bool remove_mean = a.has("--remove-mean");

  const bool windowed = a.has("--window-length");
  std::size_t length = s.size(), hop = s.size();
  if (windowed) {
    const double len = a.number_in("--window-length", NAN, Range::above(0), "a length", "s");
    const double step = a.number_in("--step", len, Range::above(0), "a hop", "s");
    length = static_cast<std::size_t>(std::llround(len * s.rate));
    hop = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(step * s.rate)));
    if (length < 2 || length > s.size())
      throw Error("--window-length " + format_number(len) + " s gives " + std::to_string(length) +
                  " samples; it must hold 2 to " + std::to_string(s.size()) + " samples");
  }
  const std::vector<WindowIndicators> windows = sliding_indicators(s.x, length, hop, remove_mean);
  out.write(stats_result(s, windows, unit, remove_mean, windowed));
  return 0;
}

}  // namespace ohmdem::post::cli
