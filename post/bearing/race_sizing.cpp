// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/race_sizing.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace ohmdem::post {

RaceToSize race_to_size(const Diagnosis &found, const DiagnoseOptions &o, const std::string &by,
                        DefectLocation &l)
{
  RaceToSize r;
  r.defect = found.defect;
  r.f = found.frequency_hz;
  if (!o.assume_defect.empty() && o.assume_defect != found.defect) {
    r.defect = o.assume_defect;
    r.f = r.defect == "inner" ? found.kinematics.bpfi : found.kinematics.bpfo;
    r.assumed = true;
  }
  if (r.defect == "ball") {
    l.method = "not determined by " + by + " (a ball defect)";
    l.position_note = "not determined: the defective ball cannot be told from the others";
    return r;
  }
  if (r.defect != "inner" && r.defect != "outer") {
    l.method = "not applicable";
    return r;
  }
  l.position_note = "not determined: " + by + " gives the size only";
  r.race = true;
  return r;
}

void set_method(DefectLocation &l, const RaceToSize &r, const std::string &note)
{
  l.method =
      r.assumed ? "assumed " + r.defect + " defect ({diagnose.assume_defect}); " + note : note;
}

double race_arc_m(const BearingGeometry &g, const std::string &defect, double size_deg)
{
  const double c = g.db * std::cos(g.contact_angle_deg * kPi / 180);
  return size_deg * kPi / 180 * (defect == "inner" ? (g.dp - c) / 2 : (g.dp + c) / 2);
}

std::size_t strongest_in(const std::vector<double> &v, double at, double reach, std::size_t lo,
                         std::size_t hi)
{
  const auto a = static_cast<std::size_t>(std::max(at - reach, static_cast<double>(lo)));
  const auto b = std::min(static_cast<std::size_t>(at + reach), hi);
  std::size_t mx = a;
  for (std::size_t i = a; i <= b; ++i)
    if (v[i] > v[mx]) mx = i;
  return mx;
}

}  // namespace ohmdem::post
