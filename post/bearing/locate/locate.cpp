// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/locate/locate.h"

#include <cmath>

#include "core/error.h"

namespace ohmdem::post {

void apply_validity(DefectLocation &l, const MethodValidity &v)
{
  if (l.valid && !v.validated) {
    l.size_reading_deg = l.size_deg;
    l.valid = false;
    l.method = "not determined: the method's reading " + format_number(l.size_deg, 4) +
               " deg is outside every case its report measured (" + v.cases + "; " + v.report +
               "); " + l.method;
  }
  if (!l.valid) {
    l.size_deg = l.size_lo_deg = l.size_hi_deg = l.arc_m = std::nan("");
    l.interval_coverage.clear();
  } else if (l.interval_coverage.empty()) {
    l.size_lo_deg = l.size_hi_deg = std::nan("");  // never measured to cover: none reported
  }
}

namespace {

bool race(const std::string &defect)
{
  return defect == "inner" || defect == "outer";
}

}  // namespace

DefectLocation locate(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o)
{
  const SizeMethod &sm = o.size_method ? *o.size_method : default_size_method(s, o);
  const PlaceMethod &pm = o.place_method ? *o.place_method : default_place_method(s);
  const std::string sized = o.assume_defect.empty() ? found.defect : o.assume_defect;
  DefectLocation l;
  const std::string why = refused_by(sm, s, o);
  if (!why.empty() && race(sized)) {
    l.method = "not determined: " + why;
  } else {
    l = sm.size(s, found, o);
    apply_validity(l, sm.validity());
  }
  l.size_method = sm.name();
  l.size_status = l.valid            ? LocateStatus::determined
                  : race(sized)      ? LocateStatus::not_determined
                                     : LocateStatus::not_applicable;
  if (!sm.places() || !why.empty()) {
    const std::string no_place = refused_by(pm, s, o);
    DefectLocation p;
    if (!no_place.empty())
      p.position_note = no_place;
    else
      p = pm.place(s, found, o);
    l.position_deg = p.position_deg;
    l.position_lo_deg = p.position_lo_deg;
    l.position_hi_deg = p.position_hi_deg;
    l.position_reference = p.position_reference;
    l.position_modulo_deg = p.position_modulo_deg;
    l.position_note = race(sized) || sized == "ball" ? p.position_note : "";
    l.place_method = pm.name();
  } else {
    l.place_method = sm.name();
  }
  l.position_status = std::isfinite(l.position_deg) ? LocateStatus::determined
                      : race(sized)                 ? LocateStatus::not_determined
                                                    : LocateStatus::not_applicable;
  return l;
}

}  // namespace ohmdem::post
