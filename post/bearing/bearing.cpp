// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/bearing.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"

namespace ohmdem::post {

BearingGeometry CatalogEntry::geometry() const
{
  return {name, nb, db, (dext + dinn) / 2, 0.0};
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
  validate(e.geometry());
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
  return read_catalog_file(dir + "/" + name, name);
}

BearingGeometry bearing_preset(const std::string &name)
{
  return catalog_entry(default_catalog_dir(), name).geometry();
}

void validate(const BearingGeometry &g)
{
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
  const double r = g.db / g.dp * std::cos(g.contact_angle_deg * kPi / 180);
  DefectFrequencies f;
  f.fr = fr;
  f.ftf = fr / 2 * (1 - r);
  f.bpfo = g.nb * f.ftf;
  f.bpfi = g.nb * fr / 2 * (1 + r);
  f.bsf = g.dp / (2 * g.db) * fr * (1 - r * r);
  return f;
}

}  // namespace ohmdem::post
