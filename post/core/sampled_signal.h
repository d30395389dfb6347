// SPDX-License-Identifier: GPL-2.0-or-later
// A uniformly sampled signal, the input of every analysis, and the operations that produce one
// from time-stamped samples (uniformity check, optional resampling) or restrict it in time.
#ifndef OHMDEM_POST_SAMPLED_SIGNAL_H
#define OHMDEM_POST_SAMPLED_SIGNAL_H

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/row_lines.h"

namespace ohmdem::post {

using MetaList = std::vector<std::pair<std::string, std::string>>;

struct Signal {
  std::vector<double> x;
  double rate = 0;   // sampling rate (Hz)
  double t0 = 0;     // time of x[0] (s)
  std::string name;  // quantity (column) name
  MetaList meta;     // provenance: source, column, time base, ...

  std::size_t size() const { return x.size(); }
  double time(std::size_t i) const { return t0 + static_cast<double>(i) / rate; }
  double duration() const { return static_cast<double>(x.size()) / rate; }
};

// Builds a uniform signal from strictly increasing time stamps t (s). The stamps count as
// uniform when every step is within 1 % of the mean step and every stamp within 1 % of a step of
// the straight line through the first and last (plus the printed resolution `t_resolution`).
// Otherwise, if `resample`, x is linearly interpolated onto a grid with the median step; if not,
// Error. `line_of_row` (optional, may be empty) and `where` name the source in messages.
Signal make_uniform(const std::vector<double> &t, std::vector<double> x, double t_resolution,
                    bool resample, const std::string &where, const RowLines &line_of_row = {});

// Throws Error if the signal has fewer than `n` samples, naming `what` needs them.
void require_samples(const Signal &s, std::size_t n, const std::string &what);

std::string format_number(double v, int digits = 6);

}  // namespace ohmdem::post

#endif
