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

bool CatalogEntry::has(const std::string &variable) const
{
  for (const auto &v : variables)
    if (v.first == variable) return true;
  return false;
}

double CatalogEntry::pitch_diameter() const
{
  if (dpw > 0) return dpw;
  return dext > 0 && dinn > 0 ? (dext + dinn) / 2 : 0;
}

namespace {

std::vector<std::string> words_of(const std::string &line)
{
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> w;
  for (std::string t; in >> t;) w.push_back(t);
  return w;
}

bool is_name_line(const std::vector<std::string> &w)
{
  return !w.empty() && (w[0] == "alias" || w[0] == "others" || w[0] == "refer");
}

// The rules between the values of one file (doc/bearing_catalog.md, "Syntax").
void check_entry(CatalogEntry &e, const std::map<std::string, double> &values)
{
  const std::string &path = e.path;
  auto get = [&](const char *key, const char *what) {
    const auto it = values.find(key);
    if (it == values.end()) return 0.0;
    if (!(it->second > 0))
      throw CatalogError(path + ": " + key + " (" + what + ") must be > 0, got " +
                         format_value(it->second));
    return it->second;
  };
  const double nb = get("Nb", "number of balls");
  if (nb != std::floor(nb) || nb > 1000)
    throw CatalogError(path + ": Nb (number of balls) must be an integer in 1..1000, got " +
                       format_value(nb));
  e.nb = static_cast<int>(nb);
  e.db = get("Db", "ball diameter, m");
  e.dext = get("Dext", "outer race diameter, m");
  e.dinn = get("Dinn", "inner race diameter, m");
  e.rc_ext = get("Rcext", "outer groove radius, m");
  e.rc_inn = get("Rcinn", "inner groove radius, m");
  e.dpw = get("Dpw", "pitch diameter, m");
  e.bpfo = get("BPFO", "ball pass frequency, outer race, x fr");
  e.bpfi = get("BPFI", "ball pass frequency, inner race, x fr");
  e.bsf = get("BSF", "ball spin frequency, x fr");
  e.ftf = get("FTF", "cage frequency, x fr");
  const bool geometry = e.nb > 0 || e.db > 0;
  if (!geometry && !(e.bpfo > 0 || e.bpfi > 0))
    throw CatalogError(path +
                       ": gives neither a ball set (Nb and Db) nor defect-frequency factors "
                       "(BPFO and BPFI): missing 'variable Nb index VALUE'");
  if (geometry && !(e.nb > 0 && e.db > 0))
    throw CatalogError(path + ": missing 'variable " + (e.nb > 0 ? "Db" : "Nb") +
                       " index VALUE' (Nb and Db come together)");
  if ((e.dext > 0) != (e.dinn > 0))
    throw CatalogError(path + ": missing 'variable " + (e.dext > 0 ? "Dinn" : "Dext") +
                       " index VALUE' (Dext and Dinn come together; or give Dpw alone)");
  if ((e.dext > 0 || e.dpw > 0) && !geometry)
    throw CatalogError(path + ": a pitch or race diameter needs Nb and Db");
  if (e.dext > 0 && !(e.dext > e.dinn))
    throw CatalogError(path + ": Dext (" + format_value(e.dext) + " m) must exceed Dinn (" +
                       format_value(e.dinn) + " m)");
  if (e.dext > 0 && e.dpw > 0 && std::fabs(e.dpw - (e.dext + e.dinn) / 2) > 1e-9 * e.dpw)
    throw CatalogError(path + ": Dpw (" + format_value(e.dpw) +
                       " m) differs from (Dext + Dinn)/2 (" + format_value((e.dext + e.dinn) / 2) +
                       " m): give one of them");
  if (e.pitch_diameter() > 0 && !(e.pitch_diameter() > e.db))
    throw CatalogError(path + ": the pitch diameter (" + format_value(e.pitch_diameter()) +
                       " m) must exceed Db (" + format_value(e.db) + " m)");
  if ((e.bpfo > 0) != (e.bpfi > 0) || ((e.bsf > 0 || e.ftf > 0) && !(e.bpfo > 0)))
    throw CatalogError(path + ": missing 'variable " + (e.bpfo > 0 ? "BPFI" : "BPFO") +
                       " index VALUE' (factors need BPFO and BPFI; BSF and FTF are optional)");
  // Z = BPFO + BPFI for any contact angle: the factors must describe a whole ball count.
  const double z = e.bpfo + e.bpfi;
  if (e.bpfo > 0 && (!(e.bpfi > e.bpfo) || std::fabs(z - std::round(z)) > 0.01 * z))
    throw CatalogError(path + ": BPFO + BPFI (" + format_value(z) +
                       ") must be the number of balls, a whole number, with BPFI > BPFO");
  if (e.bpfo > 0 && e.nb > 0 && std::lround(z) != e.nb)
    throw CatalogError(path + ": BPFO + BPFI (" + format_value(z) + ") must equal Nb (" +
                       std::to_string(e.nb) + ")");
}

}  // namespace

CatalogEntry read_catalog_file(const std::string &path, const std::string &name)
{
  std::ifstream in(path);
  if (!in) throw CatalogError("cannot open bearing catalog file '" + path + "'");
  CatalogEntry e;
  e.name = name;
  e.requested = name;
  e.path = path;
  std::map<std::string, double> values;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const std::vector<std::string> w = words_of(line);
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
  check_entry(e, values);
  return e;
}

NameFile read_name_file(const std::string &path)
{
  std::ifstream in(path);
  if (!in) throw CatalogError("cannot open bearing catalog file '" + path + "'");
  NameFile f;
  std::vector<std::string> others;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> w = words_of(line);
    if (w.empty()) continue;
    if (!is_name_line(w)) {
      if (f.kind.empty() && others.empty()) return {};  // an entry: variable lines
      throw CatalogError(path + ":" + std::to_string(number) +
                         ": expected 'alias NAME', 'others NAME...' or 'refer NAME...', got '" +
                         line + "'");
    }
    for (std::size_t i = 1; i < w.size(); ++i)
      if (!is_catalog_name(w[i]))
        throw CatalogError(path + ":" + std::to_string(number) + ": '" + w[i] +
                           "' is not a catalog name");
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (w[0] == "others") {
      others.insert(others.end(), w.begin() + 1, w.end());
    } else if (!f.kind.empty()) {
      throw CatalogError(where + "a second '" + w[0] + "' line");
    } else if (w.size() < 2 || (w[0] == "alias" && w.size() != 2)) {
      throw CatalogError(where +
                         (w[0] == "alias" ? "expected 'alias NAME'" : "expected 'refer NAME...'"));
    } else {
      f.kind = w[0];
      f.names.assign(w.begin() + 1, w.end());
    }
  }
  if (f.kind.empty() && !others.empty())
    throw CatalogError(path + ": an 'others' line needs an 'alias NAME' line");
  if (f.kind == "refer" && !others.empty())
    throw CatalogError(path + ": 'others' goes with 'alias', not with 'refer'");
  f.names.insert(f.names.end(), others.begin(), others.end());
  return f;
}

CatalogEntry read_entry(const std::string &dir, const std::string &name)
{
  const std::vector<std::string> names = catalog_names(dir);
  auto known = [&](const std::string &n) {
    return is_catalog_name(n) && std::find(names.begin(), names.end(), n) != names.end();
  };
  if (!known(name)) throw CatalogError("bearing '" + name + "' is not in the catalog " + dir);
  const std::string path = dir + "/" + name;
  const NameFile f = read_name_file(path);
  if (f.kind == "refer") {
    std::string use;
    for (std::size_t i = 0; i < f.names.size(); ++i)
      use += (i == 0 ? "" : i + 1 == f.names.size() ? " or " : ", ") + f.names[i];
    throw CatalogError("bearing '" + name + "' has no sourced geometry in the catalog: use " + use +
                       " (" + path + " says why)");
  }
  if (f.kind.empty()) return read_catalog_file(path, name);
  const std::string &target = f.names.front();
  if (!known(target) || !read_name_file(dir + "/" + target).kind.empty())
    throw CatalogError(path + ": alias " + target + " is no entry of " + dir);
  CatalogEntry e = read_catalog_file(dir + "/" + target, target);
  e.requested = name;
  e.others.assign(f.names.begin() + 1, f.names.end());
  return e;
}

namespace {

std::string format_length(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);  // Dpw +- Db of mm data: no binary noise
  return buf;
}

}  // namespace

DeckGeometry deck_geometry_of(const CatalogEntry *entry,
                              const std::vector<std::pair<std::string, std::string>> &given)
{
  auto given_text = [&](const std::string &key) {
    for (const auto &g : given)
      if (g.first == key) return g.second;
    return std::string();
  };
  auto given_value = [&](const std::string &key) {
    double v = 0;
    const std::string t = given_text(key);
    return !t.empty() && parse_number(t, v) ? v : 0.0;
  };
  DeckGeometry out;
  const bool dpw_given = !given_text("Dpw").empty();
  if (dpw_given && !(given_value("Dpw") > 0)) {
    out.error = "deck variable Dpw: the pitch diameter must be a number > 0 (m), got '" +
                given_text("Dpw") + "'";
    return out;
  }
  if (dpw_given && !given_text("Dext").empty() && !given_text("Dinn").empty()) {
    out.error =
        "deck variables Dpw, Dext and Dinn: give the pitch diameter Dpw or the race "
        "diameters Dext and Dinn, not both";
    return out;
  }
  const double db = !given_text("Db").empty() ? given_value("Db") : entry ? entry->db : 0;
  const double dpw = dpw_given ? given_value("Dpw") : entry ? entry->pitch_diameter() : 0;
  std::vector<std::string> missing;
  if (entry && entry->nb == 0 && given_text("Nb").empty())
    missing.push_back("-var Nb N (number of balls" +
                      (entry->has_factors() ? "; its factors give BPFO + BPFI = " +
                                                  format_value(entry->bpfo + entry->bpfi) + ")"
                                            : std::string(")")));
  if (entry && entry->db == 0 && given_text("Db").empty())
    missing.emplace_back("-var Db M (ball diameter)");
  for (const char *race : {"Dext", "Dinn"}) {
    const bool outer = race[1] == 'e';
    if (!given_text(race).empty() || (!dpw_given && entry && entry->has(race))) continue;
    if (!(dpw > 0)) {
      if (entry && outer)
        missing.emplace_back(
            "-var Dpw M (pitch diameter; the races are then Dpw + Db and Dpw - Db) or -var Dext "
            "M -var Dinn M");
      continue;
    }
    if (!(db > 0)) continue;
    out.define.emplace_back(race, format_length(outer ? dpw + db : dpw - db));
    // the entry's own races, so that run.json says the entry ran unless -var changed them
    if (entry && !dpw_given && entry->pitch_diameter() > 0 && entry->db > 0)
      out.copies.emplace_back(race, format_length(outer ? entry->pitch_diameter() + entry->db
                                                        : entry->pitch_diameter() - entry->db));
    else if (entry)
      out.copies.emplace_back(race, "-1");
  }
  if (!missing.empty()) {
    out.error = "bearing '" + entry->requested + "' (" + entry->path +
                ") does not give what the simulation needs (not published for it; the catalog "
                "holds no guess). Give it with ";
    for (std::size_t i = 0; i < missing.size(); ++i) out.error += (i ? ", " : "") + missing[i];
    out.error += " (lengths in m)";
  }
  return out;
}

}  // namespace ohmdem::catalog
