// SPDX-License-Identifier: GPL-2.0-or-later
// Hamrock-Dowson film thickness; see ehl_film.h.
#include "lubrication/ehl_film.h"

#include <cmath>

#include "lubrication/keyed_cache.h"

namespace ohmdem::lubrication {

namespace {

// What depends on the oil and the race only, for every contact at every step: the films are
// h = P u^e_u w^e_w with P from eta, E', Rx, alpha (the powers of U, G and W but u and w) and
// the ellipticity factor from k. Two logarithms and two exponentials per call remain.
struct Prefactors {
  double central = 0, minimum = 0;
};
struct Ellipticity {
  double central = 0, minimum = 0;
};

const Prefactors &prefactors(const FilmInput &in)
{
  thread_local KeyedCache<4, Prefactors> cache;
  return cache.get({in.eta, in.e_prime, in.rx, in.alpha}, [](const std::array<double, 4> &k) {
    const double eta = k[0], e = k[1], rx = k[2], alpha = k[3];
    const double lu = std::log(eta / (e * rx)), lg = std::log(alpha * e),
                 lw = std::log(1.0 / (e * rx * rx));
    return Prefactors{rx * 2.69 * std::exp(0.67 * lu + 0.53 * lg - 0.067 * lw),
                      rx * 3.63 * std::exp(0.68 * lu + 0.49 * lg - 0.073 * lw)};
  });
}

// a/b of a contact varies in its last bits from load to load (a and b are each rounded):
// eight slots hold the few values of two races.
const Ellipticity &ellipticity(double k)
{
  thread_local KeyedCache<1, Ellipticity, 8> cache;
  return cache.get({k}, [](const std::array<double, 1> &key) {
    return Ellipticity{1.0 - 0.61 * std::exp(-0.73 * key[0]), 1.0 - std::exp(-0.68 * key[0])};
  });
}

}  // namespace

Film hamrock_dowson(const FilmInput &in)
{
  Film f;
  if (!(in.speed > 0.0) || !(in.load > 0.0)) return f;
  const Prefactors &p = prefactors(in);
  const Ellipticity &e = ellipticity(in.k);
  // Shared logarithms: each power is one exp of a sum.
  const double ls = std::log(in.speed), lw = std::log(in.load);
  f.central = p.central * std::exp(0.67 * ls - 0.067 * lw) * e.central;
  f.minimum = p.minimum * std::exp(0.68 * ls - 0.073 * lw) * e.minimum;
  return f;
}

}  // namespace ohmdem::lubrication
