// SPDX-License-Identifier: GPL-2.0-or-later
// The kinematic lines of a bearing - shaft, cage, outer race, inner race, ball spin, ball
// defect - as one table: peak labels, fault bands, plot markers, the `frequencies` listing and
// the diagnosis columns all read it, in this order.
#ifndef OHMDEM_POST_DEFECT_LINES_H
#define OHMDEM_POST_DEFECT_LINES_H

#include <string>
#include <vector>

#include "bearing/bearing.h"

namespace ohmdem::post {

struct DefectLine {
  const char *key;      // JSON key: fr, ftf, bpfo, bpfi, bsf, two_bsf
  const char *name;     // label stem: "BPFO" (harmonic h reads "hxBPFO")
  const char *title;    // "BPFO (outer race)"
  const char *formula;  // "Nb FTF" (Harris, doc/ohmdem-post.md "frequencies")
  const char *defect;   // the defect family repeating at this line: inner, outer, ball, cage; ""
  bool fault_line;      // a defect's own line, marked on figures: FTF, BPFO, BPFI, 2BSF
  const char *color;    // its colour on figures
  double (*of)(const DefectFrequencies &k);  // the line's frequency (orders when fr = 1)
};

// fr, FTF, BPFO, BPFI, BSF, 2BSF
const std::vector<DefectLine> &defect_lines();

// "hxNAME" (h > 1) or "NAME"; `always` writes "1xNAME" too (peak labels, fault bands).
std::string harmonic_label(int h, const DefectLine &line, bool always = true);

// The nearest harmonic h = 1..harmonics of a line within relative `tolerance` of f
// ("3xBPFO"), "" if none; on a tie the later line of the table wins.
std::string label_frequency(double f, const DefectFrequencies &k, int harmonics, double tolerance);

// The fastest defect line: max(BPFI, BPFO, 2 BSF).
double highest_defect_frequency(const DefectFrequencies &k);

// The narrowest kurtogram band that carries `harmonics` harmonics of the fastest defect line
// (10 % margin), at most a quarter of the sampling rate.
double defect_band_width(const DefectFrequencies &k, int harmonics, double rate);

}  // namespace ohmdem::post

#endif
