// SPDX-License-Identifier: GPL-2.0-or-later
// The one answer of sizing and placing a bearing defect: its size with an interval and its
// place, each with a status and the reason when it is not determined (locate/size_method.h,
// locate/place_method.h make it).
#ifndef OHMDEM_POST_BEARING_LOCATE_DEFECT_LOCATION_H
#define OHMDEM_POST_BEARING_LOCATE_DEFECT_LOCATION_H

#include <cstddef>
#include <limits>
#include <string>

namespace ohmdem::post {

// determined: a value inside the validity its method's report measured; not_determined: the
// method ran and the record does not give it, or the value lies outside that validity (the
// reason says which); not_applicable: nothing to size (no race defect identified).
enum class LocateStatus { determined, not_determined, not_applicable };
const char *status_name(LocateStatus s);

struct DefectLocation {
  bool valid = false;  // a size was read (before the validity check: status says if it holds)
  LocateStatus size_status = LocateStatus::not_applicable;
  std::string size_method;  // the method's name in the table (locate/size_method.h)
  std::string method;       // how the size was found, or why not (the reason)
  double size_deg = std::numeric_limits<double>::quiet_NaN();
  double size_lo_deg = std::numeric_limits<double>::quiet_NaN();  // NaN: no bound
  double size_hi_deg = std::numeric_limits<double>::quiet_NaN();
  // the interval's coverage as measured on cases with a known size (the method's table entry);
  // empty: never measured (then no interval is reported)
  std::string interval_coverage;
  double arc_m = std::numeric_limits<double>::quiet_NaN();
  double pulse_height = 0;    // the relative jump used
  std::string height_source;  // "theory: ..." or "{diagnose.pulse_height}"
  std::size_t passes = 0;
  double window_rel_area_s = std::numeric_limits<double>::quiet_NaN();  // for the model's curve
  double pass_energy = std::numeric_limits<double>::quiet_NaN();        // accel-curve (V^2 s)
  double edge_width_s = std::numeric_limits<double>::quiet_NaN();       // for the width curve
  // a value the method read but does not report as a size (outside its validity), else NaN
  double size_reading_deg = std::numeric_limits<double>::quiet_NaN();
  LocateStatus position_status = LocateStatus::not_applicable;
  std::string place_method;  // the place method's name in the table
  double position_deg = std::numeric_limits<double>::quiet_NaN();
  double position_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double position_hi_deg = std::numeric_limits<double>::quiet_NaN();
  std::string position_reference;  // "shaft zero", "load direction", or empty
  // an outer pit under a radial load: the position is known modulo this (360/Nb), else NaN
  double position_modulo_deg = std::numeric_limits<double>::quiet_NaN();
  std::string position_note;  // why not determined
  std::string depth_note;     // what the record says of the depth
  // the template fit's distance of an outer pit from the load direction (deg, even in the
  // angle), and its interval; NaN without a bank of several angles
  double fit_angle_deg = std::numeric_limits<double>::quiet_NaN();
  double fit_angle_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double fit_angle_hi_deg = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace ohmdem::post

#endif
