// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/defect_lines.h"

#include <algorithm>
#include <cmath>

namespace ohmdem::post {

const std::vector<DefectLine> &defect_lines()
{
  static const std::vector<DefectLine> table = {
      {"fr", "fr", "shaft", "fr", "", false, "", [](const DefectFrequencies &k) { return k.fr; }},
      {"ftf", "FTF", "FTF (cage)", "fr/2 (1 - d/D cos b)", "cage", true, "#7f8c8d",
       [](const DefectFrequencies &k) { return k.ftf; }},
      {"bpfo", "BPFO", "BPFO (outer race)", "Nb FTF", "outer", true, "#2471a3",
       [](const DefectFrequencies &k) { return k.bpfo; }},
      {"bpfi", "BPFI", "BPFI (inner race)", "Nb fr/2 (1 + d/D cos b)", "inner", true, "#c0392b",
       [](const DefectFrequencies &k) { return k.bpfi; }},
      {"bsf", "BSF", "BSF (ball spin)", "D/(2d) fr (1 - (d/D cos b)^2)", "ball", false, "",
       [](const DefectFrequencies &k) { return k.bsf; }},
      // a ball defect strikes the inner and the outer race once per spin
      {"two_bsf", "2BSF", "2xBSF (ball defect)", "2 BSF", "ball", true, "#239b56",
       [](const DefectFrequencies &k) { return 2 * k.bsf; }},
  };
  return table;
}

std::string harmonic_label(int h, const DefectLine &line, bool always)
{
  return (always || h > 1 ? std::to_string(h) + "x" : std::string()) + line.name;
}

std::string label_frequency(double f, const DefectFrequencies &k, int harmonics, double tol)
{
  std::string best;
  double best_err = tol;
  for (const DefectLine &line : defect_lines())
    for (int h = 1; h <= harmonics; ++h) {
      const double err = std::fabs(f - h * line.of(k)) / (h * line.of(k));
      if (err <= best_err) {
        best_err = err;
        best = harmonic_label(h, line);
      }
    }
  return best;
}

double highest_defect_frequency(const DefectFrequencies &k)
{
  return std::max({k.bpfi, k.bpfo, 2 * k.bsf});
}

double defect_band_width(const DefectFrequencies &k, int harmonics, double rate)
{
  return std::min(rate / 4, 1.1 * harmonics * highest_defect_frequency(k));
}

}  // namespace ohmdem::post
