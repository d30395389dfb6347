// SPDX-License-Identifier: GPL-2.0-or-later
// The place methods of an identified race defect, as the size methods (locate/size_method.h):
// a name, what they need, a check, place(record, identified defect) -> the place fields of a
// DefectLocation (position_deg, its interval, its reference, the modulo of an outer pit),
// registered by name.
#ifndef OHMDEM_POST_BEARING_LOCATE_PLACE_METHOD_H
#define OHMDEM_POST_BEARING_LOCATE_PLACE_METHOD_H

#include <string>
#include <vector>

#include "bearing/locate/size_method.h"

namespace ohmdem::post {

class PlaceMethod {
 public:
  virtual ~PlaceMethod() = default;
  virtual const char *name() const = 0;
  virtual const char *summary() const = 0;
  virtual MethodNeeds needs() const = 0;
  virtual MethodValidity validity() const = 0;
  // The place of the race defect found (or {diagnose.assume_defect}): the position fields of the
  // result (and position_note saying why not), the others left as they are.
  virtual DefectLocation place(const Signal &s, const Diagnosis &found,
                               const DiagnoseOptions &o) const = 0;
};

std::string refused_by(const PlaceMethod &m, const Signal &s, const DiagnoseOptions &o);
const std::vector<const PlaceMethod *> &place_methods();
const PlaceMethod &place_method(const std::string &name);  // SettingError for an unknown name
std::string place_method_names();
// The electrical level's pulses, or the vibration record's passes.
const PlaceMethod &default_place_method(const Signal &s);

}  // namespace ohmdem::post

#endif
