// SPDX-License-Identifier: GPL-2.0-or-later
// an outer-race defect's angle from the load direction under a radial load, from the
// phase of its pulses within the ball-pass cycle. A healthy bearing under a radial load has a
// smooth R modulation at BPFO (the load-zone's ball loads change as the balls pass the load
// line, and R is largest when one ball sits on the line); a pulse occurs when a ball is at the
// pit. Both repeat at BPFO, so the pulse's phase after the modulation's maximum is Nb times the
// pit's angle from the load line, in the balls' direction of travel: the angle is known modulo
// the ball spacing 360/Nb (doc/methods/size_pulse_area.md).
#ifndef OHMDEM_POST_BEARING_OUTER_POSITION_H
#define OHMDEM_POST_BEARING_OUTER_POSITION_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

// The two phases (radians, in the BPFO cycle) of one folded stretch.
struct FoldPhases {
  bool valid = false;
  double pulse = 0;          // the pulse's centroid
  double modulation = 0;     // the smooth modulation's maximum, the pulse masked
  double rel_amplitude = 0;  // the modulation's amplitude over the level
};

// Bins of the BPFO fold, blocks for the standard error, the half-width (cycles) masked around
// the pulse when fitting the modulation, the share of the pulse's peak that bounds its centroid.
constexpr int kPhaseBins = 64, kPhaseBlocks = 8;
constexpr double kPulseMask = 0.25, kCentroidLevel = 0.3;
// The pulse's rise over the level must exceed this many times the modulation's amplitude (the
// simulated pits: 17 to 190 times; a healthy fold's crest: about once).
constexpr double kPulseOverModulation = 4;
// The angle's error beyond its block-to-block scatter (deg on the race): the fold's pulse
// shape and the modulation's own shape move the lag the same way in every block. Its standard
// deviation is the RMS of the place errors of the placed outer pits under a radial load of the
// validation protocol's tuning seed (studies/protocol.py, 200 cases of seed 5: 6 pits placed,
// errors -0.79 to 3.73 deg, RMS 1.96 deg); it joins the interval in quadrature.
constexpr double kSystematicDeg = 1.96;

// x[from, to) folded at f (Hz) sampled at rate; invalid when the fold has an empty bin or no
// pulse rises above the level and the modulation. Exposed for the tests.
FoldPhases fold_phases(const std::vector<double> &x, std::size_t from, std::size_t to, double rate,
                       double f);

struct OuterPosition {
  bool valid = false;
  std::string note;  // why not
  // from the load direction (the load zone's centre), in the balls' direction of travel, in
  // [-spacing/2, spacing/2): the pit lies at angle + k * spacing, k an integer the phase
  // cannot tell
  double angle_deg = std::numeric_limits<double>::quiet_NaN();
  double half_width_deg = std::numeric_limits<double>::quiet_NaN();  // the 95 % interval's
  double spacing_deg = std::numeric_limits<double>::quiet_NaN();     // 360 / Nb
  double se_deg = 0;  // standard error from the record's blocks
  std::size_t blocks = 0;
  double rel_modulation = 0;
};

// x sampled at rate, the outer defect's pulses at f (Hz, the refined BPFO), nb balls; the
// pulse's entry-to-exit crossing (s, NaN if unknown) bounds where its centroid may lie.
OuterPosition outer_position(const std::vector<double> &x, double rate, double f, int nb,
                             double crossing_s);

}  // namespace ohmdem::post

#endif
