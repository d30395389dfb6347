// SPDX-License-Identifier: GPL-2.0-or-later
// An outer pit's templates between the bank's angles from the load direction (issue 26). The
// bank holds folds at a few angles (the study's: 0, 15, 30, 45, 60 deg); a pit between two of
// them has a pulse neither holds (held-out pits at 22.5 deg fitted their nearest angle with a
// reduced chi-square of 14-39). The pulse's height and shape change smoothly along the load zone,
// so the fold at an angle between two of the bank's is taken as the mix of theirs, linear in the
// angle, both aligned at their entries; the fit then runs over a continuous-looking angle grid
// and its angle interval needs no widening by the bank's step.
#ifndef OHMDEM_POST_BEARING_TEMPLATE_ANGLE_H
#define OHMDEM_POST_BEARING_TEMPLATE_ANGLE_H

#include <vector>

#include "bearing/pulse_template.h"

namespace ohmdem::post {

// Steps between two neighbouring angles of the bank (15 deg: 1.9 deg apart, finer than the
// fit's angle interval on the study's records, so the interval's rise is resolved).
constexpr int kAngleSteps = 8;

// The templates at `steps` angles per interval of `angles` (sorted, every size at every angle;
// the bank's own angles included, its folds unchanged), and the angles in `dense`. Each mixed
// template keeps the lower angle's length and entry; its error per bin is the mix's.
std::vector<PulseTemplate> between_angles(const std::vector<PulseTemplate> &t,
                                          const std::vector<double> &sizes,
                                          const std::vector<double> &angles, int steps,
                                          std::vector<double> &dense);

struct LocatedDefect;
// An outer pit's place: the phase gives it modulo the ball spacing (outer_position.h), the
// template fit its distance from the load direction (the pulse's shape along the load zone, even
// in the angle). Where the fit's angle interval overlaps one branch's phase interval alone
// (both are estimates: at the 30 deg pits they differ by up to 1.5 deg, more than either
// interval's half-width), that branch is the place; otherwise it stays modulo the spacing and
// the note says why.
void pick_branch(LocatedDefect &l, const TemplateFit &f);

}  // namespace ohmdem::post

#endif
