// SPDX-License-Identifier: GPL-2.0-or-later
// Fault bands of a spectrum: for each harmonic of each kinematic line of a bearing, the band
// h f (1 +- tolerance), its largest bin (interpolated) and its power.
#ifndef OHMDEM_POST_FAULT_BANDS_H
#define OHMDEM_POST_FAULT_BANDS_H

#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {

struct FaultBand {
  std::string label;                  // "2xBPFO"
  double lo = 0, hi = 0, center = 0;  // Hz
  double peak_amplitude = 0;          // interpolated amplitude (amplitude scaling), else the bin's
  double peak_frequency = 0;          // Hz
  double power = 0;                   // sum of A^2/2 over the band's bins / ENBW in bins
};

// Harmonics 1..harmonics of every line of defect_lines(), in table order; the band is at least
// one bin wide on each side; bands reaching fs/2 or holding no bin above 0 Hz are left out.
// A windowed sine spreads its power A^2/2 over ENBW/df bins, hence the division.
std::vector<FaultBand> fault_bands(const Spectrum &s, const DefectFrequencies &k, int harmonics,
                                   double tolerance);

}  // namespace ohmdem::post

#endif
