// SPDX-License-Identifier: GPL-2.0-or-later
// The least-squares line through samples y[0..n) against their index, on the centred abscissa
// i - (n-1)/2 (so that the mean and the slope are uncorrelated and the sums stay small): what a
// linear detrend removes and what a uniform time column's step is estimated from.
#ifndef OHMDEM_POST_CORE_INDEX_LINE_FIT_H
#define OHMDEM_POST_CORE_INDEX_LINE_FIT_H

#include <cstddef>

namespace ohmdem::post {

struct IndexLineFit {
  double mean = 0;    // the line's value at the centre index
  double slope = 0;   // per index step (0 for fewer than 2 samples)
  double centre = 0;  // (n-1)/2
  double at(std::size_t i) const { return mean + slope * (static_cast<double>(i) - centre); }
};

inline IndexLineFit fit_line_to_index(const double *y, std::size_t n)
{
  IndexLineFit f;
  if (n == 0) return f;
  const double dn = static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) f.mean += y[i];
  f.mean /= dn;
  f.centre = (dn - 1) / 2;
  if (n < 2) return f;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) - f.centre;
    sxy += u * (y[i] - f.mean);
    sxx += u * u;
  }
  f.slope = sxy / sxx;
  return f;
}

}  // namespace ohmdem::post

#endif
