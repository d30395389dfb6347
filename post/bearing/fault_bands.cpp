// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/fault_bands.h"

#include <algorithm>
#include <cmath>

#include "bearing/defect_lines.h"
#include "dsp/peaks.h"

namespace ohmdem::post {

std::vector<FaultBand> fault_bands(const Spectrum &s, const DefectFrequencies &k, int harmonics,
                                   double tol)
{
  const double enbw_bins = s.enbw_hz / s.df;
  std::vector<FaultBand> out;
  for (const DefectLine &line : defect_lines())
    for (int h = 1; h <= harmonics; ++h) {
      const double c = h * line.of(k), half = std::max(tol * c, s.df);
      const double lo = c - half, hi = c + half;
      if (hi >= s.rate / 2) continue;
      std::size_t best = 0;
      double power = 0;
      for (std::size_t b = static_cast<std::size_t>(std::max(0.0, std::ceil(lo / s.df)));
           b < s.bins() && s.frequency(b) <= hi; ++b) {
        const double amp = amplitude_of(s, b);
        power += amp * amp / 2;
        if (best == 0 || amp > amplitude_of(s, best)) best = b;
      }
      if (best == 0) continue;
      const Peak p = refine_peak(s, best);
      out.push_back({harmonic_label(h, line), lo, hi, c,
                     s.scaling == Scaling::Amplitude ? p.value : amplitude_of(s, best), p.frequency,
                     power / enbw_bins});
    }
  return out;
}

}  // namespace ohmdem::post
