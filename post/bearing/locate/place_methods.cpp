// SPDX-License-Identifier: GPL-2.0-or-later
// The place methods' table (locate/place_method.h): the electrical pulses (an inner pit from
// its passes through the load zone against the shaft angle, an outer pit from the pulses' phase
// after the ball-pass modulation, modulo the ball spacing) and an accelerometer's passes (an
// inner pit from the passes' energy against the shaft angle, an outer pit from the events'
// direction on two axes).
#include "bearing/defect_size.h"
#include "bearing/diagnose.h"
#include "bearing/event_direction.h"
#include "bearing/locate/place_method.h"
#include "bearing/pass_energy.h"
#include "bearing/race_sizing.h"
#include "core/error.h"

namespace ohmdem::post {

namespace {

// the place fields of `from` into `to`
void take_place(DefectLocation &to, const DefectLocation &from)
{
  to.position_deg = from.position_deg;
  to.position_lo_deg = from.position_lo_deg;
  to.position_hi_deg = from.position_hi_deg;
  to.position_reference = from.position_reference;
  to.position_modulo_deg = from.position_modulo_deg;
  to.position_note = from.position_note;
}

class PulsesPlace : public PlaceMethod {
 public:
  const char *name() const override { return "pulses"; }
  const char *summary() const override
  {
    return "the electrical pulses under a radial load: an inner pit's passes through the load "
           "zone against the shaft angle; an outer pit's phase after the ball-pass modulation "
           "(modulo the ball spacing)";
  }
  MethodNeeds needs() const override { return {RecordKind::level, {"radial"}, "", false}; }
  MethodValidity validity() const override
  {
    return {"an electrical level record under a radial load; inner: with a shaft angle, "
            "0.3-3 deg pits; outer: 1-3 deg pits 0-60 deg from the load",
            "inner: every interval held the place (within 1.8 deg at 20 kHz); outer, modulo the "
            "ball spacing: 17-18 of 20 at 10-50 kHz",
            "doc/post/size.md", true};
  }
  DefectLocation place(const Signal &s, const Diagnosis &found,
                       const DiagnoseOptions &o) const override
  {
    // the place does not use the jump: a unit one stands in where none is given
    DiagnoseOptions po = o;
    if (!(po.pulse_height > 0) && po.curve_size_deg.empty()) po.pulse_height = 1;
    const DefectLocation a = locate_defect(s, found, po);
    DefectLocation l;
    take_place(l, a);
    return l;
  }
};

class PassesPlace : public PlaceMethod {
 public:
  const char *name() const override { return "passes"; }
  const char *summary() const override
  {
    return "an accelerometer's passes under a radial load: an inner pit's pass energy against "
           "the shaft angle; an outer pit's events' direction on two axes (the second axis: {diagnose.across})";
  }
  MethodNeeds needs() const override { return {RecordKind::vibration, {"radial"}, "", true}; }
  MethodValidity validity() const override
  {
    return {"a vibration record under a radial load; inner: with a shaft angle; outer: with the "
            "second axis",
            "inner: 93 of 96 simulated pits within 10 deg, every interval holding the place",
            "doc/post/size.md", true};
  }
  DefectLocation place(const Signal &s, const Diagnosis &found,
                       const DiagnoseOptions &o) const override
  {
    DefectLocation l;
    const RaceToSize r = race_to_size(found, o, "the record", l);
    if (!r.race) return l;
    place_inner_by_pass_energy(s, r, o, l);
    place_outer_by_event_direction(s, r, o, l);
    return l;
  }
};

const PulsesPlace kPulses;
const PassesPlace kPasses;

}  // namespace

const std::vector<const PlaceMethod *> &place_methods()
{
  static const std::vector<const PlaceMethod *> table{&kPulses, &kPasses};
  return table;
}

std::string place_method_names()
{
  std::string n;
  for (const PlaceMethod *m : place_methods()) n += (n.empty() ? "" : " or ") + std::string(m->name());
  return n;
}

const PlaceMethod &place_method(const std::string &name)
{
  for (const PlaceMethod *m : place_methods())
    if (name == m->name()) return *m;
  throw SettingError("{diagnose.place_method} must be " + place_method_names() + ", got '" +
                     name + "'");
}

std::string refused_by(const PlaceMethod &m, const Signal &s, const DiagnoseOptions &o)
{
  const MethodNeeds n = m.needs();
  const RecordKind k = record_kind(s.x);
  if (k != n.record)
    return std::string("not determined: the ") + m.name() + " place method reads a " +
           kind_name(n.record) + " record; this one is a " + kind_name(k) + " record";
  (void)o;  // the load: each method's note says what a balanced load leaves open
  return "";
}

const PlaceMethod &default_place_method(const Signal &s)
{
  return record_kind(s.x) == RecordKind::level ? static_cast<const PlaceMethod &>(kPulses)
                                               : kPasses;
}

}  // namespace ohmdem::post
