// SPDX-License-Identifier: GPL-2.0-or-later
// An outer pit's templates between the bank's angles from the load direction. The
// bank holds folds at several angles (the study's: every 2.5 deg from 0 to 60); a pit between
// two of them has a pulse neither holds (held-out pits at 22.5 deg fitted the nearest of angles
// 15 deg apart with a reduced chi-square of 14-39). Between two close angles the fold is taken
// as the mix of theirs, linear in the angle, both aligned at their entries; the fit then runs
// over a continuous-looking angle grid. The shape does not follow the angle smoothly over wider
// steps (it changes with where the other balls are, which repeats every ball spacing), so the
// mix holds only between close angles, and the bank states the fitted angle's own error on
// pits between its angles (`angle_error_deg`), which widens the interval.
#ifndef OHMDEM_POST_BEARING_TEMPLATE_ANGLE_H
#define OHMDEM_POST_BEARING_TEMPLATE_ANGLE_H

#include <vector>

#include "bearing/pulse_template.h"

namespace ohmdem::post {

// Steps between two neighbouring angles of the bank (2.5 deg: 0.31 deg apart, finer than the
// fit's angle interval on the study's records, so the interval's rise is resolved).
constexpr int kAngleSteps = 8;

// The templates at `steps` angles per interval of `angles` (sorted, every size at every angle;
// the bank's own angles included, its folds unchanged), and the angles in `dense`. Each mixed
// template keeps the lower angle's length and entry; its error per bin is the mix's.
std::vector<PulseTemplate> between_angles(const std::vector<PulseTemplate> &t,
                                          const std::vector<double> &sizes,
                                          const std::vector<double> &angles, int steps,
                                          std::vector<double> &dense);

struct DefectLocation;
// An outer pit's place: the phase gives it modulo the ball spacing (outer_position.h), the
// template fit its distance from the load direction (the pulse's shape along the load zone, even
// in the angle). Where the fit's angle interval, widened by the bank's angle error, overlaps one
// branch's phase interval alone (both are estimates), that branch is the place; otherwise, or
// when the bank states no angle error, it stays modulo the spacing and the note says why.
void pick_branch(DefectLocation &l, const TemplateFit &f);

}  // namespace ohmdem::post

#endif
