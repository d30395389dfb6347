// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/locate/locate.h"

#include <cmath>

#include "bearing/pulse_template.h"
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

// An outer pit under a radial load: the electrical methods' model data (the jump, the curves, a
// bank of one angle) are the load line's; the phase places the pit only modulo the ball
// spacing, so whether it lies there is not known, and pits 45-60 deg off it read 20-25 % small.
// Only a bank with angles from the load (its fit gives the distance) sizes it.
bool off_centre_unknown(const Signal &s, const std::string &sized, const DiagnoseOptions &o)
{
  if (sized != "outer" || o.load != "radial" || record_kind(s.x) != RecordKind::level)
    return false;
  if (!o.template_bank) return true;
  std::vector<double> sizes, angles;
  bank_grid(*o.template_bank, sizes, angles);
  return angles.size() < 2;
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
    if (l.valid && off_centre_unknown(s, sized, o)) {
      l.size_reading_deg = l.size_deg;
      l.valid = false;
      l.method = "not determined: an outer pit under a radial load is sized on the load line's "
                 "model (its jump, curve or bank of one angle), and the phase places it only "
                 "modulo the ball spacing, so its distance from the load line is not known (pits "
                 "45-60 deg off it read 20-25 % small): give a bank with angles from the load "
                 "({diagnose.model}, studies/template_bank.py); " + l.method;
    }
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
