// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/ball_evidence.h"

#include <cmath>

#include "core/error.h"

namespace ohmdem::post {

namespace {

// A ball carries load only over the part of a cage turn it spends in the load zone: its
// impulses are deeply amplitude-modulated at FTF, a modulation depth m putting sidebands of m / 2
// of the carrier on each side. Both sidebands together at half the carrier or more (m >= 0.5)
// are a ball's; sidebands found by chance in noise stand near 0.2 (the independent model of
// tests/post/synthetic_bearing.py: a ball's 1.7, an outer race's 0 to 0.22).
constexpr double kBallModulation = 0.5;

}  // namespace

bool CageModulation::present() const
{
  return cage_margin_db > 0 && ball_sidebands >= 2 && sideband_ratio >= kBallModulation;
}

std::string CageModulation::describe() const
{
  return "FTF comb margin " + format_number(cage_margin_db, 3) + " dB, " +
         std::to_string(ball_sidebands) + " FTF sidebands on the ball comb, " +
         format_number(sideband_ratio, 3) + " of their carriers";
}

CageModulation cage_modulation(const std::vector<FamilyScore> &families)
{
  CageModulation m;
  for (const FamilyScore &f : families) {
    if (f.defect == "cage") m.cage_margin_db = f.margin;
    if (f.defect != "ball") continue;
    // the carriers of harmonics that have a sideband; sidebands to their carriers
    double carriers = 0, sidebands = 0;
    const Evidence *carrier = nullptr;
    bool counted = false;
    for (const Evidence &e : f.evidence) {
      if (e.label.find("FTF") == std::string::npos) {
        carrier = &e;
        counted = false;
        continue;
      }
      ++m.ball_sidebands;
      sidebands += e.amplitude;
      if (carrier && !counted) carriers += carrier->amplitude;
      counted = true;
    }
    m.sideband_ratio = carriers > 0 ? sidebands / carriers : 0;
  }
  return m;
}

const FamilyScore *ball_or_race(const std::vector<FamilyScore> &families, const FamilyScore *best,
                                double tolerance, std::string &note)
{
  note.clear();
  if (!best || best->defect == "cage") return best;
  const FamilyScore *ball = nullptr;
  for (const FamilyScore &f : families)
    if (f.defect == "ball") ball = &f;
  if (!ball || ball->harmonics == 0) return best;
  // the race family nearest the ball's comb; overlapping when their matched or kinematic
  // fundamentals lie within the tolerance of each other
  const FamilyScore *race = nullptr;
  for (const FamilyScore &f : families) {
    if (f.defect != "inner" && f.defect != "outer") continue;
    if (best->defect != "ball" && &f != best) continue;
    const bool overlap = std::fabs(f.nominal_hz / ball->nominal_hz - 1) <= tolerance ||
                         std::fabs(f.frequency_hz / ball->frequency_hz - 1) <= tolerance;
    if (overlap && f.score > 0 && (!race || f.margin > race->margin)) race = &f;
  }
  if (!race) return best;
  const CageModulation m = cage_modulation(families);
  const FamilyScore *chosen = m.present() ? ball : race;
  note = "the " + ball->label + " and " + race->label + " combs (" +
         format_number(ball->frequency_hz) + " and " + format_number(race->frequency_hz) +
         " Hz) claim the same lines: " +
         (m.present() ? "the record is modulated at FTF (" + m.describe() + "), a ball's signature"
                      : "no FTF modulation (" + m.describe() + "): a race defect's pulses") +
         ", reported as " + chosen->defect;
  return chosen;
}

}  // namespace ohmdem::post
