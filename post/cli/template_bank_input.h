// SPDX-License-Identifier: GPL-2.0-or-later
// diagnose --template-bank FILE: the model's pulse templates (bearing/pulse_template.h), read and
// checked against the record's own acquisition chain (the header `acquire` writes).
//
// The file: '#' header lines 'KEY: VALUE' - bearing, defect, load, sampling rate (Hz), lowpass
// (the chain's anti-alias filter as acquire states it), bin (s), model error - then one line per
// template: SIZE_DEG ANGLE_DEG N Y_1 ... Y_N SE_1 ... SE_N (the fold relative to the level, its
// standard error per bin). studies/template_bank.py writes it.
#ifndef OHMDEM_POST_CLI_TEMPLATE_BANK_INPUT_H
#define OHMDEM_POST_CLI_TEMPLATE_BANK_INPUT_H

#include <optional>
#include <string>

#include "bearing/bearing.h"
#include "bearing/pulse_template.h"
#include "core/sampled_signal.h"
#include "dsp/butterworth.h"

namespace ohmdem::post::cli {

struct BankFile {
  TemplateBank bank;
  std::string bearing, defect, load, lowpass;
  double rate = 0;
  // '# fold period: grid|fine' (absent: grid, the banks made before it was stated)
  bool fine_fold_period = false;
};

// Throws Error naming --template-bank and the expected form on any malformed line.
BankFile read_template_bank(const std::string &path);

// Refuses a bank of another rate, anti-alias filter (when `record_path`'s header states one),
// bearing, defect or load; `bearing` null, `defect` and `load` empty: not checked. The bearing
// is matched by its geometry's values (the catalog entry the bank names against the record's),
// never by its name.
void check_bank(const BankFile &b, const Signal &s, const std::string &record_path,
                const BearingGeometry *bearing, const std::string &defect,
                const std::string &load);

// The same ball set: ball count, diameters and contact angle equal to the last digit printed.
bool same_geometry(const BearingGeometry &a, const BearingGeometry &b);
std::string geometry_text(const BearingGeometry &g);

// The lowpass line of an acquired record's header ("Butterworth order 4, cut-off 8000 Hz
// (-3 dB)"), without the input rate's sections; empty when the header has none.
std::string record_lowpass(const std::string &record_path);

// The anti-alias filter an acquired record's header states ("Butterworth order 4, cut-off 8000
// Hz (-3 dB), 2 sections at 1000000 Hz, ..."; acquire's causal filter at its input rate); none
// when the header states none or no such filter.
std::optional<RecordFilter> record_filter(const std::string &record_path);

// --pulse-fold-out FILE: the record's fold, for a bank (header lines, then 'Y SE' per bin).
void write_fold(const std::string &path, const FoldedPulse &p, const std::string &record_path);

}  // namespace ohmdem::post::cli

#endif
