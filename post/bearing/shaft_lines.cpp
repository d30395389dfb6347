// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/shaft_lines.h"

#include <algorithm>
#include <cmath>

namespace ohmdem::post {

namespace {

constexpr double kLine = 6;  // dB above the floor: a line

double credit(double p)
{
  return std::clamp(p - kLine, 0.0, 34.0);
}

// Most prominent bin within +-w bins of f (npos if out of range).
std::size_t best_near(const std::vector<double> &p, double df, double f, double w)
{
  const double u = f / df;
  const double lo = std::max(1.0, std::ceil(u - w));
  const double hi = std::min(static_cast<double>(p.size() - 1), std::floor(u + w));
  if (!(lo <= hi)) return static_cast<std::size_t>(-1);
  std::size_t best = static_cast<std::size_t>(lo);
  for (auto k = static_cast<std::size_t>(lo); k <= static_cast<std::size_t>(hi); ++k)
    if (p[k] > p[best]) best = k;
  return best;
}

// A comb of lines at m f0 (m = 1..10, those below Nyquist): mean credit >= kShaftCombMin, at
// least half of the harmonics lines (>= 6 dB), among them the 1x or the 2x. A line-rich defect
// spectrum (a cage knock train, harmonics every 31.5 Hz) has lines near some m x 50 Hz, not
// this.
bool is_comb(const std::vector<double> &p, double df, double f0, double width)
{
  const double f_top = df * static_cast<double>(p.size() - 1);
  const int H = static_cast<int>(std::min(10.0, std::floor(f_top / f0)));
  if (H < 2) return false;
  double total = 0;
  int lines = 0;
  bool low = false;
  for (int m = 1; m <= H; ++m) {
    const std::size_t k = best_near(p, df, m * f0, width);
    if (k == static_cast<std::size_t>(-1)) continue;
    total += credit(p[k]);
    if (p[k] >= kLine) {
      ++lines;
      low = low || m <= 2;
    }
  }
  return total / H >= kShaftCombMin && 2 * lines >= H && low;
}

}  // namespace

std::size_t mask_harmonics(const std::vector<double> &p, double df, double f0,
                           std::vector<char> &mask, bool only_a_comb)
{
  const double f_top = df * static_cast<double>(p.size() - 1);
  // a mains frequency is exact: its lines are looked for within +-1 bin
  const double width = only_a_comb ? 1 : 2;
  if (only_a_comb && !is_comb(p, df, f0, width)) return 0;
  std::size_t lines = 0;
  for (int m = 1; f0 > 0 && m * f0 < f_top; ++m) {
    const std::size_t k = best_near(p, df, m * f0, width + 5e-5 * m * f0 / df);
    if (k == static_cast<std::size_t>(-1) || p[k] < kLine) continue;
    ++lines;
    mask[k] = 1;
    for (std::size_t j = k + 1; j < p.size() && p[j] >= kLine && p[j] <= p[j - 1]; ++j) mask[j] = 1;
    for (std::size_t j = k; j > 1 && p[j - 1] >= kLine && p[j - 1] <= p[j]; --j) mask[j - 1] = 1;
  }
  return lines;
}

ShaftLines shaft_lines(const std::vector<double> &p, double df, double fr, double tolerance)
{
  ShaftLines sl;
  sl.fr = fr;
  sl.mask.assign(p.size(), 0);
  const double f_top = df * static_cast<double>(p.size() - 1);
  sl.harmonics =
      static_cast<int>(std::clamp(std::floor(f_top / (fr * (1 + tolerance))), 0.0, 10.0));
  if (sl.harmonics == 0 || p.size() < 3) return sl;
  const double step = df / 4;
  const int nsteps = static_cast<int>(std::ceil(tolerance * fr / step));
  double best_total = -1, best_f = fr;
  for (int i = -nsteps; i <= nsteps; ++i) {
    const double f = fr + i * step;
    double total = 0;
    for (int m = 1; m <= sl.harmonics; ++m) {
      const std::size_t k = best_near(p, df, m * f, 1.5);
      if (k != static_cast<std::size_t>(-1)) total += credit(p[k]);
    }
    if (total > best_total + 1e-12 ||
        (std::fabs(total - best_total) <= 1e-12 && std::fabs(f - fr) < std::fabs(best_f - fr))) {
      best_total = total;
      best_f = f;
    }
  }
  // A best comb at the edge of the search lies beyond it: no refinement, the stated speed's
  // own comb or none (a defect's lines pulling the search, not the shaft's)
  if (nsteps > 0 && std::abs(best_f - fr) >= (nsteps - 0.5) * step) {
    best_f = fr;
    best_total = 0;
    for (int m = 1; m <= sl.harmonics; ++m) {
      const std::size_t k = best_near(p, df, m * fr, 1.5);
      if (k != static_cast<std::size_t>(-1)) best_total += credit(p[k]);
    }
  }
  sl.comb_db = best_total / sl.harmonics;
  // A shaft comb has its low harmonics (unbalance, misalignment); a defect's train whose
  // harmonics fall near some m fr (an outer-race train at 5.15 fr on a short record) has not.
  sl.estimated = is_comb(p, df, best_f, 1.5);
  if (sl.estimated) {
    // the credit-weighted mean of the harmonics' bins over their order: the highest harmonics
    // weigh most in precision, as they should
    double num = 0, den = 0;
    for (int m = 1; m <= sl.harmonics; ++m) {
      const std::size_t k = best_near(p, df, m * best_f, 1.5);
      if (k == static_cast<std::size_t>(-1)) continue;
      const double c = credit(p[k]) * m;
      num += c * static_cast<double>(k) * df / m;
      den += c;
    }
    if (den > 0) sl.fr = num / den;
    if (!(std::fabs(sl.fr / fr - 1) <= tolerance)) {
      sl.fr = fr;
      sl.estimated = false;
    }
  }
  // no comb, nothing to mask: a line-rich defect spectrum keeps its lines near m fr
  if (sl.estimated) sl.lines = mask_harmonics(p, df, sl.fr, sl.mask);
  return sl;
}

}  // namespace ohmdem::post
