// SPDX-License-Identifier: GPL-2.0-or-later
// The shaft angle from a once-per-revolution pulse train (a tachometer or keyphasor channel):
// what an instrument records of the shaft's angle, where the simulator writes the angle itself.
#ifndef OHMDEM_POST_DSP_TACHO_ANGLE_H
#define OHMDEM_POST_DSP_TACHO_ANGLE_H

#include <cstddef>
#include <vector>

namespace ohmdem::post {

struct TachoAngle {
  std::vector<double> theta;  // rad per sample: 2 pi k at the k-th pulse's rising edge
  std::size_t pulses = 0;     // rising edges found
};

// The angle at each sample of the `pulses` channel: 0 at the first pulse's rising edge and
// 2 pi k at the k-th, linear in between (the speed constant within a revolution), extrapolated
// before the first edge and after the last at their revolutions' speeds. An edge is where the
// channel rises through the middle of its range, counted again only after it has fallen below a
// quarter of the range (noise on an edge counts once); its time is interpolated between the two
// samples. Throws ohmdem::post::Error, saying why, for a flat channel or fewer than two edges.
TachoAngle angle_from_tacho(const std::vector<double> &pulses);

}  // namespace ohmdem::post

#endif
