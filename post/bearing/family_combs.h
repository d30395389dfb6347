// SPDX-License-Identifier: GPL-2.0-or-later
// The defect families' harmonic combs on one spectrum (the identification stage of diagnose.h):
// each bin's prominence over the noise floor with the shaft and mains lines masked, each family's
// comb searched within the slip tolerance and scored against decoy combs, and against a healthy
// baseline when one is given.
#ifndef OHMDEM_POST_FAMILY_COMBS_H
#define OHMDEM_POST_FAMILY_COMBS_H

#include <vector>

#include "bearing/diagnose.h"
#include "bearing/shaft_lines.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {

// A spectrum with each bin's prominence over the running-median noise floor.
struct AnalysedSpectrum {
  const char *name;
  Spectrum s;
  std::vector<double> prominence_db;  // shaft and mains lines masked (0 dB)
  std::vector<double> open_db;        // nothing masked: what decoy combs see
  ShaftLines shaft;                   // the shaft-harmonic lines, masked: no family may claim them
};

// x's spectrum (Hann, mean removed, padded x2) analysed: the shaft lines near fr and the mains
// combs at mains_hz (where they stand out) masked.
AnalysedSpectrum analyse(const char *name, const std::vector<double> &x, double rate, double fr,
                         double tolerance, const std::vector<double> &mains_hz);

// The four families of defect frequencies k on a (inner, outer, ball, cage): the ball family is
// the better of the 2 BSF and the BSF combs.
std::vector<FamilyScore> families(const AnalysedSpectrum &a, const DefectFrequencies &k,
                                  const DiagnoseOptions &opt);

// The record's families against a healthy baseline analysed the same way (base).
void relative_to_baseline(std::vector<FamilyScore> &record, const AnalysedSpectrum &base);

}  // namespace ohmdem::post

#endif
