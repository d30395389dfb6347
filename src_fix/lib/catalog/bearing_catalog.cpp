// SPDX-License-Identifier: GPL-2.0-or-later
#include "catalog/bearing_catalog.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

// Set by the build (CMakeLists.txt, post/CMakeLists.txt): the source tree's catalog, and the
// installed catalog relative to the installed executable.
#ifndef OHMDEM_CATALOG_DIR
#define OHMDEM_CATALOG_DIR "inputs/bearings"
#endif
#ifndef OHMDEM_INSTALLED_CATALOG
#define OHMDEM_INSTALLED_CATALOG "../share/ohmdem/inputs/bearings"
#endif

namespace ohmdem::catalog {

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

std::string format_value(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", 6, v);
  return buf;
}

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

std::string default_catalog_dir()
{
  const char *env = std::getenv("OHMDEM_CATALOG");
  if (env && *env) return env;
  const std::string installed = installed_catalog_dir();
  return installed.empty() ? OHMDEM_CATALOG_DIR : installed;
}

bool is_catalog_name(const std::string &name)
{
  if (name.empty()) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    return alnum || c == '_' || c == '-';
  });
}

std::vector<std::string> catalog_names(const std::string &dir)
{
  std::unique_ptr<DIR, int (*)(DIR *)> d(::opendir(dir.c_str()), ::closedir);
  if (!d) throw CatalogError("bearing catalog '" + dir + "' is not a readable folder");
  std::vector<std::string> names;
  while (const dirent *e = ::readdir(d.get())) {
    const std::string n = e->d_name;
    if (n.find('.') == std::string::npos && is_regular(dir + "/" + n)) names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string joined_names(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names) s += (s.empty() ? "" : " ") + n;
  return s.empty() ? "(none)" : s;
}

CatalogEntry read_catalog_file(const std::string &path, const std::string &name)
{
  std::ifstream in(path);
  if (!in) throw CatalogError("cannot open bearing catalog file '" + path + "'");
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
      throw CatalogError(where + "expected 'variable NAME index VALUE  # source', got '" + line +
                         "'");
    double v = 0;
    if (!parse_number(w[3], v))
      throw CatalogError(where + "variable " + w[1] + ": '" + w[3] + "' is not a finite number");
    if (values.count(w[1])) throw CatalogError(where + "variable " + w[1] + " given twice");
    values[w[1]] = v;
    e.variables.emplace_back(w[1], w[3]);
  }
  auto need = [&](const char *key, const char *what) {
    const auto it = values.find(key);
    if (it == values.end())
      throw CatalogError(path + ": missing 'variable " + std::string(key) + " index VALUE' (" +
                         what + ")");
    if (!(it->second > 0))
      throw CatalogError(path + ": " + key + " (" + what + ") must be > 0, got " +
                         format_value(it->second));
    return it->second;
  };
  const double nb = need("Nb", "number of balls");
  if (nb != std::floor(nb) || nb > 1000)
    throw CatalogError(path + ": Nb (number of balls) must be an integer in 1..1000, got " +
                       format_value(nb));
  e.nb = static_cast<int>(nb);
  e.db = need("Db", "ball diameter, m");
  e.dext = need("Dext", "outer race diameter, m");
  e.dinn = need("Dinn", "inner race diameter, m");
  e.rc_ext = need("Rcext", "outer groove radius, m");
  e.rc_inn = need("Rcinn", "inner groove radius, m");
  if (!(e.dext > e.dinn))
    throw CatalogError(path + ": Dext (" + format_value(e.dext) + " m) must exceed Dinn (" +
                       format_value(e.dinn) + " m)");
  return e;
}

}  // namespace ohmdem::catalog
