// SPDX-License-Identifier: GPL-2.0-or-later
// The size of an identified defect from the width of its pulses (the clean pulse train of a
// level signal such as R(t), else the synchronous average at the matched frequency), turned
// into an angle and an arc on the defective surface (defect_angle, bearing/diagnose.h).
#ifndef OHMDEM_POST_BEARING_DEFECT_SIZE_H
#define OHMDEM_POST_BEARING_DEFECT_SIZE_H

#include "bearing/diagnose.h"

namespace ohmdem::post {

// The size estimate of `d` (its defect and matched frequency) from the record `s`.
SizeEstimate estimate_size(const Signal &s, const Diagnosis &d, const BearingGeometry &g);

// the size with an interval from the pulses' area (bearing/pulse_area.h) and the
// position where the record determines it; the rest reported as not determined.
DefectLocation locate_defect(const Signal &s, const Diagnosis &d, const DiagnoseOptions &o);

}  // namespace ohmdem::post

#endif
