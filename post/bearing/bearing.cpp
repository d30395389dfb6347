// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/bearing.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "core/constants.h"
#include "core/error.h"
#include "core/sampled_signal.h"

#ifndef OHMDEM_CATALOG_DIR
#define OHMDEM_CATALOG_DIR "inputs/bearings"
#endif
#ifndef OHMDEM_INSTALLED_CATALOG
#define OHMDEM_INSTALLED_CATALOG "../share/ohmdem/inputs/bearings"
#endif

namespace ohmdem::post {

namespace {

bool is_regular(const std::string &path)
{
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

bool is_folder(const std::string &path)
{
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// The catalog installed beside this executable (PREFIX/bin -> PREFIX/share/ohmdem/...), or ""
// when the executable runs from a build tree.
std::string installed_catalog_dir()
{
  std::string exe(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  if (n <= 0) return "";
  exe.resize(static_cast<std::size_t>(n));
  const std::string dir = exe.substr(0, exe.rfind('/')) + "/" + OHMDEM_INSTALLED_CATALOG;
  if (!is_folder(dir)) return "";
  std::unique_ptr<char, decltype(&std::free)> clean(::realpath(dir.c_str(), nullptr), std::free);
  return clean ? std::string(clean.get()) : dir;  // PREFIX/share/..., not PREFIX/bin/../share/...
}

std::string joined(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names) s += (s.empty() ? "" : " ") + n;
  return s.empty() ? "(none)" : s;
}

// "0.0126" -> 0.0126; the whole token must be a finite number.
bool parse_number(const std::string &token, double &v)
{
  if (token.empty()) return false;
  char *end = nullptr;
  errno = 0;
  v = std::strtod(token.c_str(), &end);
  return errno == 0 && end == token.c_str() + token.size() && std::isfinite(v);
}

}  // namespace

BearingGeometry CatalogEntry::geometry() const
{
  return {name, nb, db, (dext + dinn) / 2, 0.0};
}

std::string default_catalog_dir()
{
  const char *env = std::getenv("OHMDEM_CATALOG");
  if (env && *env) return env;
  const std::string installed = installed_catalog_dir();
  return installed.empty() ? OHMDEM_CATALOG_DIR : installed;
}

std::vector<std::string> catalog_names(const std::string &dir)
{
  std::unique_ptr<DIR, int (*)(DIR *)> d(::opendir(dir.c_str()), ::closedir);
  if (!d)
    throw Error("bearing catalog '" + dir +
                "' is not a readable folder (--catalog DIR or OHMDEM_CATALOG)");
  std::vector<std::string> names;
  while (const dirent *e = ::readdir(d.get())) {
    const std::string n = e->d_name;
    if (n.find('.') == std::string::npos && is_regular(dir + "/" + n)) names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  return names;
}

CatalogEntry read_catalog_file(const std::string &path, const std::string &name)
{
  std::ifstream in(path);
  if (!in) throw Error("cannot open bearing catalog file '" + path + "'");
  CatalogEntry e;
  e.name = name;
  e.path = path;
  std::map<std::string, double> values;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const std::string code = line.substr(0, line.find('#'));
    std::istringstream words(code);
    std::vector<std::string> w;
    for (std::string t; words >> t;) w.push_back(t);
    if (w.empty()) continue;  // blank or comment line
    if (w.size() != 4 || w[0] != "variable" || w[2] != "index")
      throw Error(where + "expected 'variable NAME index VALUE  # source', got '" + line + "'");
    double v = 0;
    if (!parse_number(w[3], v))
      throw Error(where + "variable " + w[1] + ": '" + w[3] + "' is not a finite number");
    if (values.count(w[1])) throw Error(where + "variable " + w[1] + " given twice");
    values[w[1]] = v;
    e.variables.emplace_back(w[1], w[3]);
  }
  auto need = [&](const char *key, const char *what) {
    const auto it = values.find(key);
    if (it == values.end())
      throw Error(path + ": missing 'variable " + std::string(key) + " index VALUE' (" + what +
                  ")");
    if (!(it->second > 0))
      throw Error(path + ": " + key + " (" + what + ") must be > 0, got " +
                  format_number(it->second));
    return it->second;
  };
  const double nb = need("Nb", "number of balls");
  if (nb != std::floor(nb) || nb > 1000)
    throw Error(path + ": Nb (number of balls) must be an integer in 1..1000, got " +
                format_number(nb));
  e.nb = static_cast<int>(nb);
  e.db = need("Db", "ball diameter, m");
  e.dext = need("Dext", "outer race diameter, m");
  e.dinn = need("Dinn", "inner race diameter, m");
  e.rc_ext = need("Rcext", "outer groove radius, m");
  e.rc_inn = need("Rcinn", "inner groove radius, m");
  if (!(e.dext > e.dinn))
    throw Error(path + ": Dext (" + format_number(e.dext) + " m) must exceed Dinn (" +
                format_number(e.dinn) + " m)");
  validate(e.geometry());
  return e;
}

CatalogEntry catalog_entry(const std::string &dir, const std::string &name)
{
  const std::vector<std::string> names = catalog_names(dir);
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw Error("bearing '" + name + "' is not in the catalog " + dir + "; known bearings: " +
                joined(names) + " (or give --nb --db --dp [--beta] explicitly)");
  return read_catalog_file(dir + "/" + name, name);
}

BearingGeometry bearing_preset(const std::string &name)
{
  return catalog_entry(default_catalog_dir(), name).geometry();
}

void validate(const BearingGeometry &g)
{
  if (g.nb < 1) throw Error("ball count --nb must be a positive integer");
  if (!(g.db > 0)) throw Error("ball diameter --db must be > 0 (m), got " + format_number(g.db));
  if (!(g.dp > g.db))
    throw Error("pitch diameter --dp (" + format_number(g.dp) +
                " m) must exceed the ball diameter --db (" + format_number(g.db) + " m)");
  if (!(std::fabs(g.contact_angle_deg) < 90))
    throw Error("contact angle --beta must lie in (-90, 90) degrees");
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
