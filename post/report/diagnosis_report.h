// SPDX-License-Identifier: GPL-2.0-or-later
// The three forms of a diagnosis (ohmdem-post diagnose): its JSON document, one table row for
// tables of many records, and the aligned text for reading (verdict, detection tests, families,
// evidence).
#ifndef OHMDEM_POST_REPORT_DIAGNOSIS_REPORT_H
#define OHMDEM_POST_REPORT_DIAGNOSIS_REPORT_H

#include <optional>
#include <string>
#include <vector>

#include "bearing/diagnose.h"
#include "io/json.h"
#include "report/report.h"

namespace ohmdem::post {

// What the three forms of the diagnosis show besides the Diagnosis itself.
struct DiagnosisContext {
  const DiagnoseOptions &options;
  bool in_orders;
  std::optional<std::string> run_defect;  // run.json "defect": what the run simulated
  // A simulated signal whose spread is at the numerical floor (cmd_diagnose): said in the text,
  // since its statistics (kurtosis, p-values) then describe numerical blips, not a defect.
  std::string numerical_floor = "";
  std::string speed_source = "";  // where the stated speed (options.fr) comes from
};

Json diagnosis_json(const Diagnosis &d, const DiagnosisContext &c, const MetaList &meta);

// One row for tables of many records: the verdict, the family scores, the detection tests.
Table diagnosis_row(const Diagnosis &d);

// For reading: the verdict, then the detection tests, the families and the evidence.
std::vector<Block> diagnosis_text(const Diagnosis &d, const DiagnosisContext &c);

// The size and place alone (ohmdem-post size): the defect sized, its frequency, then the same
// keys and lines as the diagnosis gives them.
Json location_json(const Diagnosis &d, const DiagnosisContext &c, const MetaList &meta);
Table location_row(const Diagnosis &d);
std::vector<Block> location_text(const Diagnosis &d, const DiagnosisContext &c);

}  // namespace ohmdem::post

#endif
