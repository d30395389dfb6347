// SPDX-License-Identifier: GPL-2.0-or-later
// The table of ohmdem-post collect: one row per run with its folder, status, swept parameters,
// window, the indicators of `stats`, the duty and optionally the diagnosis.
#ifndef OHMDEM_POST_REPORT_COLLECT_REPORT_H
#define OHMDEM_POST_REPORT_COLLECT_REPORT_H

#include <limits>
#include <string>
#include <vector>

#include "bearing/diagnose.h"
#include "dsp/stats.h"
#include "io/run_folders.h"
#include "report/report.h"

namespace ohmdem::post {

// What collect found for one run.
struct CollectedRun {
  std::string run;
  std::string status;  // finished, interrupted or failed (run.json; finished when absent)
  RunParameters params;
  std::string quantity;  // the signal's name (column)
  double t_start = 0, t_end = 0;
  Indicators ind;
  double duty = std::numeric_limits<double>::quiet_NaN();
  bool has_duty = false;
  Diagnosis diagnosis;
};

// Columns: run, status, the parameters `keys` (prefixed param_ where a key is also a fixed
// column's name), t_start_s, t_end_s, n, the indicators (with `unit` unless dimensionless),
// duty when a run has it, the diagnosis columns with `want_diagnosis`.
Table collected_table(const std::vector<CollectedRun> &results,
                      const std::vector<std::string> &keys, const std::string &unit,
                      bool want_diagnosis);

}  // namespace ohmdem::post

#endif
