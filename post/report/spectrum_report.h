// SPDX-License-Identifier: GPL-2.0-or-later
// The results of a spectrum (ohmdem-post spectrum, envelope): how it was taken, its bins, its
// peaks labelled with the bearing's defect frequencies, or its fault bands.
#ifndef OHMDEM_POST_REPORT_SPECTRUM_REPORT_H
#define OHMDEM_POST_REPORT_SPECTRUM_REPORT_H

#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "bearing/fault_bands.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "report/report.h"

namespace ohmdem::post {

// Scaling, window, detrend, segments, transform length, bin spacing, ENBW.
MetaList spectrum_meta(const Spectrum &s, Detrend d);

// The value column's name with its unit ("amplitude_ohm", "psd_ohm^2/Hz", "psd_per_Hz").
std::string spectrum_value_name(const Spectrum &s, const std::string &unit);

// frequency_Hz and `value_column` of every bin in [fmin, fmax] (JSON: the two as arrays).
Result spectrum_bins_result(const Spectrum &s, MetaList meta, const std::string &value_column,
                            double fmin, double fmax);

// The fault bands (bearing/fault_bands.h: per harmonic of fr, FTF, BPFO, BPFI, BSF, 2BSF the
// band +-tolerance, its peak and power) of a spectrum of a signal in `unit`.
Result fault_band_result(const std::vector<FaultBand> &bands, MetaList meta,
                         const std::string &unit, double tolerance);

// rank, frequency_Hz, `value_column`, prominence_dB, and with `kin` each peak's label
// (`harmonics` of each defect frequency within the relative `tolerance`); `what` the peaks are
// of ("spectrum peaks"), found with `po`.
Result spectrum_peaks_result(const std::vector<Peak> &peaks, MetaList meta,
                             const std::string &value_column, const std::string &what,
                             const PeakOptions &po, const DefectFrequencies *kin, int harmonics,
                             double tolerance);

}  // namespace ohmdem::post

#endif
