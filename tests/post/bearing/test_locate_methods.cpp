// SPDX-License-Identifier: GPL-2.0-or-later
// The size and place methods' tables (post/bearing/locate/): names, what each needs, how a
// record it cannot read is refused, and how a size outside the method's measured validity is
// turned into "not determined". The references are the tables' own contracts (an unknown name
// lists the known ones; an electrical method never sizes an accelerometer's record) and
// closed-form records (a level with pulses, a zero-mean tone).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "bearing/diagnose.h"
#include "bearing/locate/locate.h"
#include "core/error.h"

namespace ohmdem::post {
namespace {

Signal tone(double mean)
{
  Signal s;
  s.rate = 20000;
  s.name = "x";
  for (int i = 0; i < 20000; ++i) s.x.push_back(mean + std::sin(2 * 3.14159265358979 * 97 * i / s.rate));
  return s;
}

TEST(LocateMethods, UnknownNameRefusedNamingTheKnownOnes)
{
  try {
    size_method("pulse");
    FAIL() << "an unknown size method was accepted";
  } catch (const SettingError &e) {
    const std::string w = e.what();
    for (const SizeMethod *m : size_methods())
      EXPECT_NE(w.find(m->name()), std::string::npos) << w;
    EXPECT_NE(w.find("'pulse'"), std::string::npos) << w;
  }
  try {
    place_method("phase-of-the-moon");
    FAIL() << "an unknown place method was accepted";
  } catch (const SettingError &e) {
    const std::string w = e.what();
    for (const PlaceMethod *m : place_methods())
      EXPECT_NE(w.find(m->name()), std::string::npos) << w;
  }
  for (const SizeMethod *m : size_methods()) EXPECT_EQ(&size_method(m->name()), m);
}

TEST(LocateMethods, EveryMethodStatesItsNeedsAndValidity)
{
  std::set<std::string> names;
  for (const SizeMethod *m : size_methods()) {
    EXPECT_TRUE(names.insert(m->name()).second) << "two methods named " << m->name();
    EXPECT_GT(std::string(m->summary()).size(), 20u) << m->name();
    const MethodValidity v = m->validity();
    EXPECT_FALSE(v.cases.empty()) << m->name();
    EXPECT_FALSE(v.report.empty()) << m->name();
    // a validated method whose interval is printed states how often it held the truth
    if (v.validated) {
      EXPECT_NE(v.coverage.find("covered"), std::string::npos) << m->name();
    }
  }
  for (const PlaceMethod *m : place_methods()) EXPECT_FALSE(m->validity().cases.empty());
}

TEST(LocateMethods, RecordKindFromTheLevel)
{
  EXPECT_EQ(record_kind(tone(10).x), RecordKind::level);      // spread 0.07 of the mean
  EXPECT_EQ(record_kind(tone(0).x), RecordKind::vibration);   // about zero
  EXPECT_EQ(record_kind(tone(-10).x), RecordKind::vibration); // no positive level
}

TEST(LocateMethods, AMethodRefusesARecordItCannotSizeWithItsReason)
{
  DiagnoseOptions o;
  o.geometry = BearingGeometry{"test", 9, 7.94e-3, 39.04e-3, 0, std::nullopt};
  o.fr = 29.95;
  const Signal vib = tone(0), level = tone(10);
  const std::string area = refused_by(size_method("area"), vib, o);
  EXPECT_NE(area.find("electrical level record"), std::string::npos) << area;
  EXPECT_NE(area.find("this record is a vibration record"), std::string::npos) << area;
  EXPECT_EQ(refused_by(size_method("area"), level, o), "");
  const std::string di = refused_by(size_method("double-impulse"), level, o);
  EXPECT_NE(di.find("a vibration record"), std::string::npos) << di;
  // through the pipeline: an identified inner defect on a vibration record, sized by the area
  Diagnosis d;
  d.defect = "inner";
  d.frequency_hz = 162.2;
  d.kinematics.bpfi = 162.2;
  o.size_method = &size_method("area");
  const DefectLocation l = locate(vib, d, o);
  EXPECT_EQ(l.size_status, LocateStatus::not_determined);
  EXPECT_FALSE(l.valid);
  EXPECT_TRUE(std::isnan(l.size_deg));
  EXPECT_NE(l.method.find("electrical level record"), std::string::npos) << l.method;
  EXPECT_EQ(l.size_method, "area");
  // nothing identified: nothing to size
  d.defect = "none";
  EXPECT_EQ(locate(vib, d, o).size_status, LocateStatus::not_applicable);
}

TEST(LocateMethods, ASizeOutsideTheMeasuredValidityIsNotDetermined)
{
  DefectLocation l;
  l.valid = true;
  l.size_deg = 5.3;
  l.size_lo_deg = 5.0;
  l.size_hi_deg = 5.6;
  l.method = "double impulse: delay 821 us";
  MethodValidity experimental{"synthetic records only", "", "doc/post/size.md", false};
  DefectLocation e = l;
  apply_validity(e, experimental);
  EXPECT_FALSE(e.valid);
  EXPECT_TRUE(std::isnan(e.size_deg) && std::isnan(e.size_lo_deg) && std::isnan(e.size_hi_deg));
  EXPECT_DOUBLE_EQ(e.size_reading_deg, 5.3);
  EXPECT_EQ(e.method.rfind("not determined", 0), 0u) << e.method;
  EXPECT_NE(e.method.find("synthetic records only"), std::string::npos);
  // validated, but its interval never measured to cover: the value without the interval
  MethodValidity unmeasured{"fixed load", "", "doc/post/size.md", true};
  DefectLocation u = l;
  apply_validity(u, unmeasured);
  EXPECT_TRUE(u.valid);
  EXPECT_DOUBLE_EQ(u.size_deg, 5.3);
  EXPECT_TRUE(std::isnan(u.size_lo_deg) && std::isnan(u.size_hi_deg));
  // measured: kept as it is
  DefectLocation m = l;
  m.interval_coverage = "covered 114 of 120";
  apply_validity(m, unmeasured);
  EXPECT_DOUBLE_EQ(m.size_lo_deg, 5.0);
  EXPECT_DOUBLE_EQ(m.size_hi_deg, 5.6);
}

}  // namespace
}  // namespace ohmdem::post
