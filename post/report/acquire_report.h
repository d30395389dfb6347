// SPDX-License-Identifier: GPL-2.0-or-later
// The record ohmdem-post acquire writes: '#' lines (the input's metadata, each step of the
// measurement chain as it was set, the output's rate and length), then a "time value" table
// (blank-separated, or CSV) that the other commands read.
#ifndef OHMDEM_POST_REPORT_ACQUIRE_REPORT_H
#define OHMDEM_POST_REPORT_ACQUIRE_REPORT_H

#include <string>

#include "core/sampled_signal.h"
#include "dsp/acquire.h"

namespace ohmdem::post {

// What the chain's lines say besides the settings and the acquisition.
struct AcquisitionContext {
  double input_rate = 0;        // Hz
  bool rate_given = false;      // the instrument's rate was asked for (else the input's)
  bool input_referred = false;  // the noise was given in the input's unit, times |scale|
  std::string unit;             // of the output, "" if not given
};

// The title line and the input's metadata ("input <key>", the source as it is).
std::string acquisition_head(const std::string &version, const MetaList &input_meta);

// One '#' line per step of the chain, then the output's rate, samples and duration. A line
// that says which setting gave a value names it "{acquire.field}" (core/error.h).
std::string acquisition_chain(const AcquireSettings &s, const Acquisition &q,
                              const AcquisitionContext &c);

// The column header and one "time value" row per sample of `y`; with `second` (the sensor's
// second axis, sampled with y), "time value second" rows.
std::string acquisition_table(const Signal &y, const std::string &name, const Signal *second,
                              const std::string &second_name, bool csv);

}  // namespace ohmdem::post

#endif
