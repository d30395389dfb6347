// SPDX-License-Identifier: GPL-2.0-or-later
// The result of ohmdem-post stats: the indicators of each window as table rows and JSON, and one
// window also as one indicator a line with its definition.
#ifndef OHMDEM_POST_REPORT_STATS_REPORT_H
#define OHMDEM_POST_REPORT_STATS_REPORT_H

#include <string>
#include <vector>

#include "core/sampled_signal.h"
#include "dsp/stats.h"
#include "report/report.h"

namespace ohmdem::post {

// `windows` of `s` (sliding_indicators); `windowed`: the windows were asked for (else the one
// window is the whole record); `unit` of the signal ("" if unknown).
Result stats_result(const Signal &s, const std::vector<WindowIndicators> &windows,
                    const std::string &unit, bool remove_mean, bool windowed);

}  // namespace ohmdem::post

#endif
