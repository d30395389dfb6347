// SPDX-License-Identifier: GPL-2.0-or-later
// The shaft angle of a record for order tracking: an angle column (rad), a speed column
// integrated (rad/s, rpm or Hz), or our signal.txt's `angle_inner` column found automatically.
#ifndef OHMDEM_POST_CLI_SHAFT_ANGLE_H
#define OHMDEM_POST_CLI_SHAFT_ANGLE_H

#include <optional>
#include <string>
#include <vector>

#include "cli/args.h"
#include "core/sampled_signal.h"
#include "dsp/order_tracking.h"
#include "io/run_metadata.h"

namespace ohmdem::post::cli {

// --angle-column, --speed-column, --speed-unit
void add_shaft_angle_options(Args &a);

struct ShaftAngle {
  std::vector<double> theta;  // rad, one per sample of the signal
  std::string source;         // "column angle_inner (rad)", "column omega (rpm), integrated"
  SpeedSummary speed;         // rad/s
};

// The angle for the samples of `s` (same file, same window), from --angle-column or
// --speed-column; with neither, the column `angle_inner` when the input has one (our
// signal.txt), else nothing.
std::optional<ShaftAngle> measured_shaft_angle(const Args &a, const RunMetadata &meta,
                                               const Signal &s);

// A constant speed (Hz) as the angle 2 pi fr t of the samples of `s`.
ShaftAngle constant_shaft_angle(const Signal &s, double fr, const std::string &source);

}  // namespace ohmdem::post::cli

#endif
