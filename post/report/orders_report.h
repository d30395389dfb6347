// SPDX-License-Identifier: GPL-2.0-or-later
// The tables of ohmdem-post orders: the angle-domain signal, the order spectrum's bins, its
// peaks labelled with the defect orders.
#ifndef OHMDEM_POST_REPORT_ORDERS_REPORT_H
#define OHMDEM_POST_REPORT_ORDERS_REPORT_H

#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "dsp/order_tracking.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"
#include "report/report.h"

namespace ohmdem::post {

// revolution, angle_rad, `value_column`: the signal resampled at `spr` samples per revolution.
Table resampled_table(const AngleResampled &r, double spr, const std::string &value_column);

// order, `value_column`: the bins between the orders `lo` and `hi`.
Table order_bins_table(const Spectrum &sp, double lo, double hi, const std::string &value_column);

// rank, order, `value_column`, prominence_dB, and with `orders` (the defect orders) the label
// of each peak (`harmonics` of each order, within the relative `tolerance`).
Table order_peaks_table(const std::vector<Peak> &peaks, const std::string &value_column,
                        const DefectFrequencies *orders, int harmonics, double tolerance);

}  // namespace ohmdem::post

#endif
