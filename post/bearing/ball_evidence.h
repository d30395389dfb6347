// SPDX-License-Identifier: GPL-2.0-or-later
// Ball or race: a ball defect's impulses (2 BSF, a spall striking both races once per
// spin turn) are modulated at the cage frequency FTF, since the ball carries load only while the
// cage takes it through the load zone; an outer-race defect's impulses are not (the defect stands
// in the load zone) and an inner-race defect's are modulated at the shaft rate. The FTF
// modulation decides between a ball and a race family whose combs claim the same lines.
#ifndef OHMDEM_POST_BALL_EVIDENCE_H
#define OHMDEM_POST_BALL_EVIDENCE_H

#include <string>
#include <vector>

#include "bearing/diagnose.h"

namespace ohmdem::post {

// The FTF modulation of the record: the cage comb's margin above chance (dB, the better of the
// envelope and spectrum) and the FTF sidebands the ball comb found.
struct CageModulation {
  double cage_margin_db = 0;
  int ball_sidebands = 0;
  double sideband_ratio = 0;  // FTF sidebands' amplitude over their carriers' (both sides)
  bool present() const;
  std::string describe() const;
};

CageModulation cage_modulation(const std::vector<FamilyScore> &families);

// The family to report when best (inner, outer or ball, scoring) and another of those lie within
// the tolerance of each other (both combs on the same lines): the ball when the record is
// FTF-modulated, the race otherwise. Returns best when no other family overlaps it; says why in
// note (empty when nothing was decided).
const FamilyScore *ball_or_race(const std::vector<FamilyScore> &families, const FamilyScore *best,
                                double tolerance, std::string &note);

}  // namespace ohmdem::post

#endif
