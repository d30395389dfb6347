// SPDX-License-Identifier: GPL-2.0-or-later
// Hamrock-Dowson film thickness; see ehl_film.h.
#include "lubrication/ehl_film.h"

#include <cmath>

namespace ohmdem::lubrication {

Film film_prefactors(double eta, double e_prime, double rx, double alpha)
{
  const double lu = std::log(eta / (e_prime * rx)), lg = std::log(alpha * e_prime),
               lw = std::log(1.0 / (e_prime * rx * rx));
  return Film{rx * 2.69 * std::exp(0.67 * lu + 0.53 * lg - 0.067 * lw),
              rx * 3.63 * std::exp(0.68 * lu + 0.49 * lg - 0.073 * lw)};
}

Film ellipticity_factors(double k)
{
  return Film{1.0 - 0.61 * std::exp(-0.73 * k), 1.0 - std::exp(-0.68 * k)};
}

Film hamrock_dowson(const FilmInput &in)
{
  Film f;
  if (!(in.speed > 0.0) || !(in.load > 0.0)) return f;
  const Film p = film_prefactors(in.eta, in.e_prime, in.rx, in.alpha);
  const Film e = ellipticity_factors(in.k);
  // Shared logarithms: each power is one exp of a sum.
  const double ls = std::log(in.speed), lw = std::log(in.load);
  f.central = p.central * std::exp(0.67 * ls - 0.067 * lw) * e.central;
  f.minimum = p.minimum * std::exp(0.68 * ls - 0.073 * lw) * e.minimum;
  return f;
}

}  // namespace ohmdem::lubrication
