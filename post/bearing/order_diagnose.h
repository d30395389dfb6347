// SPDX-License-Identifier: GPL-2.0-or-later
// Diagnosis of a record whose shaft speed varies: the signal is resampled at constant shaft
// angle (order tracking) and diagnosed there - "sampling rate" = samples per revolution, shaft
// frequency = 1 - so that the defect lines, constant in orders, stay sharp; the results are
// given back in Hz at the record's mean shaft frequency (orders x mean fr), the pulse width in
// seconds at the mean speed. The defect size (an angle) does not depend on that conversion.
#ifndef OHMDEM_POST_ORDER_DIAGNOSE_H
#define OHMDEM_POST_ORDER_DIAGNOSE_H

#include <vector>

#include "bearing/diagnose.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

// theta: shaft angle (rad) per sample of s. opt.fr is ignored (the mean speed is used);
// opt.band (Hz) is taken at the mean speed. samples_per_rev <= 0: default_samples_per_rev.
Diagnosis diagnose_in_orders(const Signal &s, const std::vector<double> &theta, DiagnoseOptions opt,
                             double samples_per_rev = 0);

}  // namespace ohmdem::post

#endif
