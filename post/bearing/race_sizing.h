// SPDX-License-Identifier: GPL-2.0-or-later
// What diagnose's accelerometer size methods (bearing/double_impulse.h, bearing/pass_energy.h)
// share: which race defect they size, what they say of the others, the arc of a size, and how
// a pass's strongest event is found.
#ifndef OHMDEM_POST_BEARING_RACE_SIZING_H
#define OHMDEM_POST_BEARING_RACE_SIZING_H

#include <cstddef>
#include <string>
#include <vector>

#include "bearing/diagnose.h"

namespace ohmdem::post {

// The race defect to size: the one found, or o.assume_defect at its kinematic frequency.
struct RaceToSize {
  std::string defect;
  double f = 0;       // its pass frequency (Hz)
  bool race = false;  // inner or outer; else l.method (and for a ball l.position_note) say why
  bool assumed = false;
};
// `by` names the method in the notes ("the double impulse").
RaceToSize race_to_size(const Diagnosis &found, const DiagnoseOptions &o, const std::string &by,
                        DefectLocation &l);

// l.method from the method's note, marked when the defect was assumed.
void set_method(DefectLocation &l, const RaceToSize &r, const std::string &note);

// The arc (m) along the defect's race of an angular size (deg), at the ball's contact.
double race_arc_m(const BearingGeometry &g, const std::string &defect, double size_deg);

// l from a method's estimate (note, passes, valid, size_deg, size_lo_deg, size_hi_deg).
template <class Estimate>
DefectLocation take_size(DefectLocation l, const RaceToSize &r, const BearingGeometry &g,
                        const Estimate &e)
{
  set_method(l, r, e.note);
  l.passes = e.passes;
  if (!e.valid) return l;
  l.valid = true;
  l.size_deg = e.size_deg;
  l.size_lo_deg = e.size_lo_deg;
  l.size_hi_deg = e.size_hi_deg;
  l.arc_m = race_arc_m(g, r.defect, e.size_deg);
  return l;
}

// A pass's strongest event: the index of the largest v[i] for i from max(at - reach, lo) to
// min(at + reach, hi), the first on ties.
std::size_t strongest_in(const std::vector<double> &v, double at, double reach, std::size_t lo,
                         std::size_t hi);

}  // namespace ohmdem::post

#endif
