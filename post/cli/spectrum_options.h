// SPDX-License-Identifier: GPL-2.0-or-later
// Spectrum and peak options shared by `spectrum` and `envelope`.
#ifndef OHMDEM_POST_CLI_SPECTRUM_OPTIONS_H
#define OHMDEM_POST_CLI_SPECTRUM_OPTIONS_H

#include <optional>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "cli/args.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "report/report.h"
#include "report/spectrum_report.h"

namespace ohmdem::post::cli {

void add_spectrum_options(Args &a, const char *default_scale);
SpectrumOptions spectrum_options(const Args &a, std::size_t n, double rate);
void add_peak_options(Args &a);
PeakOptions peak_options(const Args &a);

// The peaks (default), every bin in [fmin, fmax] (`bins`) or the fault bands (--fault-bands),
// rendered by report/spectrum_report.
Result spectrum_result(const Args &a, const Spectrum &s, MetaList meta, const std::string &unit,
                       const std::optional<DefectFrequencies> &kin, const char *what, bool bins);

}  // namespace ohmdem::post::cli

#endif
