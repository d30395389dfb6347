// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: the keywords of model 3d; see race_settings_3d.h.
#include "BEARING/race_settings_3d.h"

#include <cmath>
#include <string>

#include "common/constants.h"
#include "support/args.h"

namespace ohmdem {

namespace {
// Which 3D keywords were given (for the checks once all are read): one bit each.
enum Given {
  kModel = 1,
  kClearance = 2,
  kAlpha0 = 4,
  kShoulder = 8,
  kAxial = 16,
  kMoment = 32,
  kPreload = 64,
  kInertia = 128,
  kTiltDamp = 256,
  kHousing = 512
};
}  // namespace

const char *race_keywords_3d()
{
  return "model clearance alpha0 shoulder axial moment preload inertia tilt_damp housing";
}

bool parse_race_keyword_3d(StyleArgs &a, const std::string &kw, RaceSettings &s)
{
  RaceSettings::Model3d &m = s.model3d;
  if (kw == "model") {
    const std::string v = a.word(kw, "2d or 3d");
    if (v != "2d" && v != "3d") a.fail(kw, "2d or 3d", v.c_str());
    m.on = v == "3d";
    m.given |= kModel;
  } else if (kw == "clearance") {
    m.clearance = a.non_negative(kw, "the radial internal clearance of the bearing, >= 0 (m)");
    m.given |= kClearance;
  } else if (kw == "alpha0") {
    const double deg = a.number(kw, "the nominal contact angle in [0, 90) degrees");
    if (!(deg >= 0.0 && deg < 90.0))
      a.fail(kw, "the nominal contact angle in [0, 90) degrees", std::to_string(deg).c_str());
    m.alpha0 = deg * kDegree;
    m.given |= kAlpha0;
  } else if (kw == "shoulder") {
    const double deg =
        a.number(kw, "the largest contact angle the groove holds, in (0, 90] degrees");
    if (!(deg > 0.0 && deg <= 90.0))
      a.fail(kw, "the largest contact angle the groove holds, in (0, 90] degrees",
             std::to_string(deg).c_str());
    m.shoulder = deg * kDegree;
    m.given |= kShoulder;
  } else if (kw == "axial") {
    m.axial = a.number(kw, "the axial force on the ring along +z (N)");
    m.given |= kAxial;
  } else if (kw == "moment") {
    m.moment = a.number(kw, "the tilting moment on the ring about z x direction (N m)");
    m.given |= kMoment;
  } else if (kw == "preload") {
    if (a.next_is("none")) {
      a.word(kw, "none");
    } else {
      m.preload = a.number(kw, "the axial position held (m), or none");
      m.preload_set = true;
    }
    m.given |= kPreload;
  } else if (kw == "inertia") {
    m.tilt_inertia = a.positive(kw, "the ring's moment of inertia about a diameter, > 0 (kg m^2)");
    m.given |= kInertia;
  } else if (kw == "tilt_damp") {
    m.tilt_damp = a.non_negative(kw, "the viscous damping of the ring's tilt, >= 0 (N m s)");
    m.given |= kTiltDamp;
  } else if (kw == "housing") {
    m.housing = a.non_negative(
        kw, "the housing's radial stiffness under the outer ring, >= 0 (N/m; 0: the ring held)");
    m.given |= kHousing;
  } else {
    return false;
  }
  return true;
}

void check_race_3d(StyleArgs &a, RaceSettings &s)
{
  RaceSettings::Model3d &m = s.model3d;
  const int given = m.given;
  if (m.shoulder == 0.0) m.shoulder = 0.5 * kPi;
  if (!m.on) {
    const char *names[] = {"clearance", "alpha0",  "shoulder",  "axial",  "moment",
                           "preload",   "inertia", "tilt_damp", "housing"};
    for (int k = 0; k < 9; ++k)
      if (given & (kClearance << k))
        a.fail(names[k], "model 3d (the keyword belongs to the 3D bearing)", "model 2d");
    return;
  }
  if (m.clearance > 0.0 && m.alpha0 > 0.0)
    a.fail("alpha0",
           "0 with a clearance: a deep-groove bearing has a clearance, an angular-contact one a "
           "nominal contact angle, not both",
           std::to_string(m.alpha0 / kDegree).c_str());
  if (given & (kAxial | kMoment | kPreload | kInertia | kTiltDamp))
    if (s.load != RaceLoad::Radial)
      a.fail("load",
             "radial with axial, moment, preload, inertia or tilt_damp (the ring free in "
             "space)",
             "another mode");
  if (s.on_housing() && s.inner)
    a.fail("housing", "a stiffness on the outer race only (the shaft is free under load radial)",
           std::to_string(m.housing).c_str());
  if (s.on_housing() && s.load != RaceLoad::None)
    a.fail("load",
           "none with housing (the outer ring's centre is held by the housing's spring, not "
           "loaded)",
           "another mode");
  if (m.preload_set && m.axial != 0.0)
    a.fail("preload",
           "none with an axial force: the axial position is held (preload) or "
           "loaded (axial), not both",
           std::to_string(m.preload).c_str());
}

}  // namespace ohmdem
