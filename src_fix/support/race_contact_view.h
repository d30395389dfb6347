// SPDX-License-Identifier: GPL-2.0-or-later
// The contact of one ball with a race, as fix bearing/race publishes it to the electrical
// computes: named fields over the race's per-atom row (its first columns, the per-atom output
// documented in doc/fix_bearing_race.md). The one place that knows the layout of that row.
#ifndef OHMDEM_RACE_CONTACT_VIEW_H
#define OHMDEM_RACE_CONTACT_VIEW_H

namespace ohmdem {

class RaceContactView {
 public:
  // Columns of the row; the race keeps its private state in the columns after kColumns (model
  // 3d: after kColumns3d, with the contact point's z and the contact angle before it).
  enum Column { kFn, kDelta, kFt, kPointX, kPointY, kInDefect, kColumns };
  enum Column3d { kPointZ = kColumns, kAngle, kColumns3d };

  explicit RaceContactView(const double *row, bool three_d = false) : row_(row), three_d_(three_d)
  {
  }
  double fn() const { return row_[kFn]; }           // normal force (N), 0 without contact
  double delta() const { return row_[kDelta]; }     // approach (m)
  double ft() const { return row_[kFt]; }           // tangential force (N)
  double point_x() const { return row_[kPointX]; }  // contact point (m)
  double point_y() const { return row_[kPointY]; }
  bool in_defect() const { return row_[kInDefect] > 0.0; }  // the point lies in a defect zone
  // model 3d: the contact point's z (m) and the signed contact angle (degrees); 0 in model 2d,
  // whose balls and contacts lie in the plane z = 0.
  double point_z() const { return three_d_ ? row_[kPointZ] : 0.0; }
  double contact_angle() const { return three_d_ ? row_[kAngle] : 0.0; }
  // A contact carries current unless its force is zero or it lies in a defect zone.
  bool conducts() const { return row_[kFn] > 0.0 && !(row_[kInDefect] > 0.0); }

 private:
  const double *row_;
  bool three_d_;
};

}  // namespace ohmdem

#endif
