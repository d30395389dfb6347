// SPDX-License-Identifier: GPL-2.0-or-later
// Where a record's level has settled: a simulated run's start-up transient (the radially free
// outer ring finds its place in the first tens of milliseconds, the level drifting by ten times
// a defect's pass-to-pass scatter) is not part of the steady record, and a kurtosis over it
// measures the drift, not pulses (a healthy radial 6208 read `outer` with it).
#ifndef OHMDEM_POST_DSP_SETTLE_H
#define OHMDEM_POST_DSP_SETTLE_H

#include <cstddef>
#include <vector>

namespace ohmdem::post {

struct Settling {
  std::size_t start = 0;   // first sample of the settled record (0: settled from the start)
  double level = 0;        // the settled level: median window mean of the record's second half
  double scatter = 0;      // robust scatter of those window means (1.4826 MAD)
  double first_drift = 0;  // the first window's mean minus the level
};

// Window means of `window` samples; the level and its scatter from the windows of the second
// half; the record settles at the first window from which kSettledWindows windows in a row lie
// within kSettleSigmas scatters of the level. Never past the middle of the record. Fewer than
// 8 windows: start 0. Throws ohmdem::post::Error for a window under 2 samples.
Settling settled_start(const std::vector<double> &x, std::size_t window);

constexpr double kSettleSigmas = 6;
constexpr int kSettledWindows = 3;

}  // namespace ohmdem::post

#endif
