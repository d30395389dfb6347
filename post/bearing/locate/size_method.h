// SPDX-License-Identifier: GPL-2.0-or-later
// The size methods of an identified race defect, in the shape of LAMMPS' granular sub-models:
// each a small class with a name, what it needs (the record's kind, load modes, model data),
// a check of its settings, what its report measured (where a size it gives holds) and
// size(record, identified defect) -> DefectLocation; registered by name in one table, from
// which the command line's checks and help come. The place methods: locate/place_method.h; the
// pipeline that runs both: locate/locate.h.
#ifndef OHMDEM_POST_BEARING_LOCATE_SIZE_METHOD_H
#define OHMDEM_POST_BEARING_LOCATE_SIZE_METHOD_H

#include <string>
#include <vector>

#include "bearing/locate/defect_location.h"

namespace ohmdem::post {

struct Diagnosis;
struct DiagnoseOptions;
struct Signal;

// level: a record that keeps a positive level with pulses on it (the electrical R, or the
// voltage across the bearing at a constant current); vibration: one oscillating about zero (an
// accelerometer's).
enum class RecordKind { level, vibration };
const char *kind_name(RecordKind k);
// A record is a level when its standard deviation is under kLevelSpread of its mean (the
// simulated R with the largest pulses studied, a 3 deg pit at the radial load's centre, spreads
// by 0.12 of its mean; an accelerometer's mean is within a fraction of its spread of zero).
constexpr double kLevelSpread = 0.5;
RecordKind record_kind(const std::vector<double> &x);

// What a method needs of the record and the settings.
struct MethodNeeds {
  RecordKind record = RecordKind::level;
  std::vector<std::string> loads;  // the load modes it sizes under; empty: any
  std::string model;               // the model data it reads ("" none), for the help
  bool constant_speed = false;     // refused when the record is analysed in the angle domain
};

// What the method's own report measured: the cases where a size it gives holds and how often
// its interval held the truth there. A size outside them is "not determined" with the reason.
struct MethodValidity {
  std::string cases;     // the cases measured (record kind, load modes, sizes, rates)
  std::string coverage;  // the interval's measured coverage; empty: never measured (no interval)
  std::string report;    // where it was measured (a page of doc/)
  // false: no case was measured where its size holds (an experimental method): its reading is
  // reported as such (size_reading_deg), never as the size
  bool validated = true;
};

class SizeMethod {
 public:
  virtual ~SizeMethod() = default;
  virtual const char *name() const = 0;
  virtual const char *summary() const = 0;  // one line of help
  virtual MethodNeeds needs() const = 0;
  virtual MethodValidity validity() const = 0;
  // Throws SettingError naming the setting ("{diagnose.size_curve}") when the options carry a
  // setting the method does not read or lack one it needs.
  virtual void check(const DiagnoseOptions &o) const = 0;
  // The size of the race defect found (or {diagnose.assume_defect}); the place where the method
  // gives one (places() true) else left to the place method.
  virtual DefectLocation size(const Signal &s, const Diagnosis &found,
                              const DiagnoseOptions &o) const = 0;
  // true: the method places the defect itself (the template fit's angle picks the outer pit's
  // branch of the phase), so its place supersedes the place method's
  virtual bool places() const { return false; }
};

// Why `m` cannot size this record ("" when it can): the record's kind or the load mode it does
// not cover.
std::string refused_by(const SizeMethod &m, const Signal &s, const DiagnoseOptions &o);

// The table, in the order of the help.
const std::vector<const SizeMethod *> &size_methods();
// The method of this name; throws SettingError naming {diagnose.size_method} and the known names.
const SizeMethod &size_method(const std::string &name);
// The names, comma-separated ("area, template, ...").
std::string size_method_names();

// The method for a record when none is named: the electrical level's template fit when the
// options hold a bank, else its pulse area; a vibration record's pass energy when they hold a
// curve, else its double impulse.
const SizeMethod &default_size_method(const Signal &s, const DiagnoseOptions &o);

}  // namespace ohmdem::post

#endif
