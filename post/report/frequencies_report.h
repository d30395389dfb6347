// SPDX-License-Identifier: GPL-2.0-or-later
// The result of ohmdem-post frequencies: a bearing's kinematic lines (fr, FTF, BPFO, BPFI, BSF,
// 2BSF) and their harmonics, as a table and as JSON.
#ifndef OHMDEM_POST_REPORT_FREQUENCIES_REPORT_H
#define OHMDEM_POST_REPORT_FREQUENCIES_REPORT_H

#include <string>

#include "bearing/bearing.h"
#include "report/report.h"

namespace ohmdem::post {

// The lines `f` of bearing `g` (its geometry from `geometry_source`), harmonics 1..`harmonics`.
Result frequencies_result(const BearingGeometry &g, const std::string &geometry_source,
                          const DefectFrequencies &f, int harmonics);

}  // namespace ohmdem::post

#endif
