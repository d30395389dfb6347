// SPDX-License-Identifier: GPL-2.0-or-later
// diagnose's second channels, recorded with the record: the other bearing's sensor,
// as another variable of the same file (--other-channel) or another file (--other-file); the
// accelerometer's second axis (--across-column).
#ifndef OHMDEM_POST_CLI_OTHER_CHANNEL_INPUT_H
#define OHMDEM_POST_CLI_OTHER_CHANNEL_INPUT_H

#include <optional>

#include "cli/args.h"
#include "core/sampled_signal.h"
#include "io/run_metadata.h"

namespace ohmdem::post::cli {

// --other-channel VARIABLE, --other-file FILE
void add_other_channel_options(Args &a);

// The other channel, read with the record's input options and time window; nothing when neither
// option is given. Refused when it does not hold the record's rate and number of samples.
std::optional<Signal> other_channel_input(const Args &a, const RunMetadata &meta, const Signal &s);

// --across-column NAME: the accelerometer's second axis in the record's file.
void add_across_options(Args &a);
// That axis, read and checked as the other channel; nothing without the option.
std::optional<Signal> across_input(const Args &a, const RunMetadata &meta, const Signal &s);

}  // namespace ohmdem::post::cli

#endif
