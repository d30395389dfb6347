// SPDX-License-Identifier: GPL-2.0-or-later
// The contact of one ball with a race, as fix bearing/race publishes it to the electrical
// computes: named fields over the race's per-atom row (its first columns, the per-atom output
// documented in doc/fix_bearing_race.md). The one place that knows the layout of that row.
#ifndef OHMDEM_RACE_CONTACT_VIEW_H
#define OHMDEM_RACE_CONTACT_VIEW_H

namespace ohmdem {

class RaceContactView {
 public:
  // Columns of the row; the race keeps its private state in the columns after kColumns.
  enum Column { kFn, kDelta, kFt, kPointX, kPointY, kInDefect, kColumns };

  explicit RaceContactView(const double *row) : row_(row) {}
  double fn() const { return row_[kFn]; }           // normal force (N), 0 without contact
  double delta() const { return row_[kDelta]; }     // approach (m)
  double ft() const { return row_[kFt]; }           // tangential force (N)
  double point_x() const { return row_[kPointX]; }  // contact point (m)
  double point_y() const { return row_[kPointY]; }
  bool in_defect() const { return row_[kInDefect] > 0.0; }  // the point lies in a defect zone
  // A contact carries current unless its force is zero or it lies in a defect zone.
  bool conducts() const { return row_[kFn] > 0.0 && !(row_[kInDefect] > 0.0); }

 private:
  const double *row_;
};

}  // namespace ohmdem

#endif
