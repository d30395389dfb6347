// SPDX-License-Identifier: GPL-2.0-or-later
// The size-and-place pipeline: the size method and the place method (named in the options, else
// chosen by the record), each refused with its reason on a record it cannot read, each size
// kept only inside the validity its method's report measured (locate/size_method.h).
#ifndef OHMDEM_POST_BEARING_LOCATE_LOCATE_H
#define OHMDEM_POST_BEARING_LOCATE_LOCATE_H

#include "bearing/diagnose.h"
#include "bearing/locate/place_method.h"
#include "bearing/locate/size_method.h"

namespace ohmdem::post {

DefectLocation locate(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o);

// A size the method read, turned into the reported one: "not determined" with the reason when
// the method is not validated; its interval dropped when its coverage was never measured.
void apply_validity(DefectLocation &l, const MethodValidity &v);

}  // namespace ohmdem::post

#endif
