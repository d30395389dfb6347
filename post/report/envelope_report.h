// SPDX-License-Identifier: GPL-2.0-or-later
// The results of ohmdem-post envelope besides its spectrum: the kurtogram's bands and the
// envelope as a time series.
#ifndef OHMDEM_POST_REPORT_ENVELOPE_REPORT_H
#define OHMDEM_POST_REPORT_ENVELOPE_REPORT_H

#include <string>
#include <vector>

#include "core/sampled_signal.h"
#include "dsp/envelope.h"
#include "report/report.h"

namespace ohmdem::post {

// Whether the best band's spectral kurtosis is more than a Gaussian record reaches,
// with the threshold and what it rests on.
std::string kurtogram_significance(const Kurtogram &kg);

// Every band of every level with its spectral kurtosis, after `meta` and the best band.
Result kurtogram_result(const Kurtogram &kg, MetaList meta);

// time_s and the envelope `env` of `s` (`unit` of the signal, "" if unknown).
Result envelope_result(const Signal &s, const std::vector<double> &env, const std::string &unit,
                       MetaList meta);

}  // namespace ohmdem::post

#endif
