// SPDX-License-Identifier: GPL-2.0-or-later
// Shaft-harmonic lines of a spectrum: the shaft frequency estimated from its
// harmonics (a tachometer off by a percent or two), and the bins those lines occupy, which a
// defect family's comb may not claim: a family whose order lies near an integer (the CWRU
// fan-end 6203: 2 BSF = 3.988 fr, BPFI = 4.947 fr, BPFO = 3.053 fr) would otherwise lock onto
// the ordinary shaft harmonics of a healthy machine.
#ifndef OHMDEM_POST_SHAFT_LINES_H
#define OHMDEM_POST_SHAFT_LINES_H

#include <cstddef>
#include <vector>

namespace ohmdem::post {

struct ShaftLines {
  double fr = 0;           // estimated shaft frequency (Hz); the given one if no line stands out
  double comb_db = 0;      // mean prominence credit (dB over 6) of harmonics 1..harmonics
  int harmonics = 0;       // harmonics the estimate used
  bool estimated = false;  // comb_db >= kShaftCombMin: the lines define fr
  std::size_t lines = 0;   // shaft-harmonic lines masked
  std::vector<char> mask;  // per bin: 1 = the lobe of a shaft-harmonic line
};

// A shaft comb this strong (mean credit, dB) defines the shaft frequency.
constexpr double kShaftCombMin = 6;

// prominence_db: each bin's prominence over the local noise floor (dB), bins at df Hz. The
// shaft frequency is searched within +-tolerance of fr (quarter-bin steps) as the comb of its
// first 10 harmonics (fewer below Nyquist) with the most prominence above 6 dB; it is estimated
// when that comb's mean credit reaches kShaftCombMin, at least half of its harmonics, the 1x or
// the 2x among them, stand 6 dB above the floor, and the estimate stays within the tolerance (a
// best comb at the search's edge is not taken: the stated fr's own comb is judged). Every
// harmonic m fr_est (m >= 1) found as a local maximum more than 6 dB above the floor within +-(2
// bins + 5e-5 m fr_est) is masked over its lobe (the bins around it still above 6 dB and falling).
// Masks (mask[k] = 1) the lobes of the lines at m f0, m >= 1, as above; returns how many.
// only_a_comb (mains, an exact frequency: lines within +-1 bin): only if the first 10 harmonics
// form a comb as the shaft's must (the supply's comb, not lines that happen to lie there).
std::size_t mask_harmonics(const std::vector<double> &prominence_db, double df, double f0,
                           std::vector<char> &mask, bool only_a_comb = false);

ShaftLines shaft_lines(const std::vector<double> &prominence_db, double df, double fr,
                       double tolerance);

}  // namespace ohmdem::post

#endif
