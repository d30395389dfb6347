// SPDX-License-Identifier: GPL-2.0-or-later
// Hamrock-Dowson film thickness; see ehl_film.h.
#include "lubrication/ehl_film.h"

#include <cmath>

namespace ohmdem::lubrication {

Film hamrock_dowson(const FilmInput &in)
{
  Film f;
  if (!(in.speed > 0.0) || !(in.load > 0.0)) return f;
  const double u = in.eta * in.speed / (in.e_prime * in.rx);
  const double g = in.alpha * in.e_prime;
  const double w = in.load / (in.e_prime * in.rx * in.rx);
  // Shared logarithms: each power is one exp of a sum.
  const double lu = std::log(u), lg = std::log(g), lw = std::log(w);
  f.central = in.rx * 2.69 * std::exp(0.67 * lu + 0.53 * lg - 0.067 * lw) *
              (1.0 - 0.61 * std::exp(-0.73 * in.k));
  f.minimum =
      in.rx * 3.63 * std::exp(0.68 * lu + 0.49 * lg - 0.073 * lw) * (1.0 - std::exp(-0.68 * in.k));
  return f;
}

}  // namespace ohmdem::lubrication
