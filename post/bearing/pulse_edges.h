// SPDX-License-Identifier: GPL-2.0-or-later
// A race defect's size from the timing of its pulses' edges, where the pulse area
// fails: a ring free to move (the radial and force loads) drops into the gap a ball in the pit
// leaves, its neighbours take the load within ~100 us and R returns to its level, then dips
// below it, before the ball leaves the pit; past ~1 deg the area stops growing. The ball's entry
// and exit stay sharp steps (the exit a strike: the ring has dropped onto it), so the time from
// the entry's steepest rise to the exit's last steep fall keeps growing with the size.
//
// The record is folded at the defect frequency on a grid finer than its samples (the passes
// fall at every sub-sample phase: equivalent-time sampling), averaged over a box of one sample,
// and the edges are read on that average: the entry at the largest rise per bin, the exit at
// the last bin, within 0.6 periods after it, whose fall exceeds a quarter of the largest fall.
// The anti-alias filter delays and widens both edges: the width is read off the model's width
// curve (simulations of the scene through the record's own acquisition chain), not taken as
// the crossing time.
#ifndef OHMDEM_POST_BEARING_PULSE_EDGES_H
#define OHMDEM_POST_BEARING_PULSE_EDGES_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

struct PulseEdges {
  bool valid = false;
  std::string note;                                           // why not
  double width_s = std::numeric_limits<double>::quiet_NaN();  // entry to exit
  double se_s = 0;         // standard error from the record's blocks
  std::size_t blocks = 0;  // contiguous blocks the standard error comes from
};

// Fine bins per sample, blocks for the standard error, exit threshold (fraction of the
// largest fall).
constexpr int kEdgeOversample = 8, kEdgeBlocks = 8;
constexpr double kExitFall = 0.25;

// x sampled at `rate`, pulses repeating at f (Hz, refined here by the synchronous contrast).
PulseEdges pulse_edge_width(const std::vector<double> &x, double rate, double f);

// The size (deg) read off a curve (sizes and values increasing) at value v, and the ends of
// the interval v -+ d; NaN outside it (hi NaN: beyond the curve's last point).
struct CurveReading {
  double size = std::numeric_limits<double>::quiet_NaN();
  double lo = std::numeric_limits<double>::quiet_NaN();
  double hi = std::numeric_limits<double>::quiet_NaN();
};
CurveReading read_on_curve(const std::vector<double> &sizes, const std::vector<double> &values,
                           double v, double d);

// The width (s) of one folded stretch x[from, to) at the repetition `period` (samples); NaN
// when the fold has a gap or no pulse. Exposed for the tests.
double folded_edge_width(const std::vector<double> &x, std::size_t from, std::size_t to,
                         double period, double rate);

}  // namespace ohmdem::post

#endif
