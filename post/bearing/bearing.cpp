// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/bearing.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

BearingGeometry CatalogEntry::geometry() const
{
  if (!has_factors() && !(nb > 0 && db > 0 && pitch_diameter() > 0))
    throw SettingError("bearing '" + requested + "' (" + path + ") gives " +
                       (nb > 0 ? "Nb and Db but no pitch diameter" : "no ball set") +
                       " (not published for it): give {geometry.dp} M (with {catalog.name}), or "
                       "{geometry.nb} {geometry.db} {geometry.dp}, or {bearing.factors} "
                       "BPFO,BPFI,BSF,FTF");
  return partial();
}

BearingGeometry CatalogEntry::partial() const
{
  BearingGeometry g{name, nb, db, pitch_diameter(), 0.0, std::nullopt};
  if (has_factors()) g.factors = complete_factors({bpfo, bpfi, bsf, ftf});
  if (g.nb == 0) g.nb = static_cast<int>(std::lround(bpfo + bpfi));
  return g;
}

DefectFactors complete_factors(DefectFactors f)
{
  // Z = BPFO + BPFI and BPFO = Z/2 (1 - r), r = d/D cos(beta): FTF = (1 - r)/2, BSF =
  // (1 - r^2)/(2 r) (Harris), as the formulas of defect_frequencies.
  const double z = f.bpfo + f.bpfi, r = 1 - 2 * f.bpfo / z;
  if (!(f.ftf > 0)) f.ftf = (1 - r) / 2;
  if (!(f.bsf > 0)) f.bsf = (1 - r * r) / (2 * r);
  return f;
}

DefectFactors parse_factors(const std::string &text)
{
  std::vector<double> v;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string token = text.substr(start, comma - start);
    char *end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if (token.empty() || *end || !std::isfinite(x) || !(x > 0))
      throw SettingError(
          "option {bearing.factors} expects BPFO,BPFI,BSF,FTF (or BPFO,BPFI): positive "
          "multiples of the shaft frequency, got '" +
          text + "'");
    v.push_back(x);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (v.size() != 2 && v.size() != 4)
    throw SettingError(
        "option {bearing.factors} expects 4 numbers BPFO,BPFI,BSF,FTF (or 2: BPFO,BPFI), got " +
        std::to_string(v.size()));
  DefectFactors f{v[0], v[1], v.size() == 4 ? v[2] : 0, v.size() == 4 ? v[3] : 0};
  if (!(f.bpfi > f.bpfo))
    throw SettingError(
        "option {bearing.factors}: BPFI must exceed BPFO (a rotating inner ring), got '" + text +
        "'");
  return complete_factors(f);
}

std::string default_catalog_dir()
{
  return catalog::default_catalog_dir();
}

std::vector<std::string> catalog_names(const std::string &dir)
{
  try {
    return catalog::catalog_names(dir);
  } catch (const catalog::CatalogError &e) {
    throw SettingError(std::string(e.what()) + " ({catalog.dir} DIR or OHMDEM_CATALOG)");
  }
}

CatalogEntry read_catalog_file(const std::string &path, const std::string &name)
{
  CatalogEntry e;
  try {
    static_cast<catalog::CatalogEntry &>(e) = catalog::read_catalog_file(path, name);
  } catch (const catalog::CatalogError &err) {
    throw Error(err.what());
  }
  return e;
}

CatalogEntry catalog_entry(const std::string &dir, const std::string &name)
{
  const std::vector<std::string> names = catalog_names(dir);
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw SettingError("bearing '" + name + "' is not in the catalog " + dir +
                       "; known bearings: " + catalog::joined_names(names) +
                       " (or give {geometry.nb} {geometry.db} {geometry.dp} "
                       "[{geometry.contact_angle_deg}] explicitly)");
  CatalogEntry e;
  try {
    static_cast<catalog::CatalogEntry &>(e) = catalog::read_entry(dir, name);  // alias resolved
  } catch (const catalog::CatalogError &err) {
    throw Error(err.what());
  }
  return e;
}

BearingGeometry bearing_preset(const std::string &name)
{
  return catalog_entry(default_catalog_dir(), name).geometry();
}

void validate(const BearingGeometry &g)
{
  if (g.factors) {
    const DefectFactors &f = *g.factors;
    for (double x : {f.bpfo, f.bpfi, f.bsf, f.ftf})
      if (!(x > 0) || !std::isfinite(x))
        throw SettingError(
            "defect-frequency factors {bearing.factors} must be positive multiples of fr");
    if (!(g.db > 0 && g.dp > 0)) return;  // factors only, or a partial ball set
  }
  if (g.nb < 1) throw SettingError("ball count {geometry.nb} must be a positive integer");
  if (!(g.db > 0))
    throw SettingError("ball diameter {geometry.db} must be > 0 (m), got " + format_number(g.db));
  if (!(g.dp > g.db))
    throw SettingError("pitch diameter {geometry.dp} (" + format_number(g.dp) +
                       " m) must exceed the ball diameter {geometry.db} (" + format_number(g.db) +
                       " m)");
  if (!(std::fabs(g.contact_angle_deg) < 90))
    throw SettingError("contact angle {geometry.contact_angle_deg} must lie in (-90, 90) degrees");
}

DefectFrequencies defect_frequencies(const BearingGeometry &g, double fr)
{
  validate(g);
  if (!(fr > 0) || !std::isfinite(fr)) throw Error("shaft frequency must be > 0 Hz");
  DefectFrequencies f;
  f.fr = fr;
  if (g.factors) {  // the maker's numbers win over the kinematic formulas
    f.ftf = g.factors->ftf * fr;
    f.bpfo = g.factors->bpfo * fr;
    f.bpfi = g.factors->bpfi * fr;
    f.bsf = g.factors->bsf * fr;
    return f;
  }
  const double r = g.db / g.dp * std::cos(g.contact_angle_deg * kPi / 180);
  f.ftf = fr / 2 * (1 - r);
  f.bpfo = g.nb * f.ftf;
  f.bpfi = g.nb * fr / 2 * (1 + r);
  f.bsf = g.dp / (2 * g.db) * fr * (1 - r * r);
  return f;
}

}  // namespace ohmdem::post
