// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricant catalog and the temperature laws; see lubricant.h.
#include "lubrication/lubricant.h"

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace ohmdem::lubrication {

namespace {

constexpr double kKelvin = 273.15;

double log_log(double nu)
{
  return std::log10(std::log10(nu + 0.7));
}

bool is_name(const std::string &s)
{
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

bool is_folder(const std::string &p)
{
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::vector<std::string> names_in(const std::string &dir)
{
  std::vector<std::string> names;
  std::unique_ptr<DIR, int (*)(DIR *)> d(::opendir(dir.c_str()), ::closedir);
  if (!d) return names;
  while (const dirent *e = ::readdir(d.get())) {
    const std::string n = e->d_name;
    if (n.find('.') == std::string::npos && is_name(n)) names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

double walther_viscosity(double nu40, double nu100, double temperature_c)
{
  const double l40 = std::log10(40.0 + kKelvin), l100 = std::log10(100.0 + kKelvin);
  const double b = (log_log(nu40) - log_log(nu100)) / (l100 - l40);
  const double a = log_log(nu40) + b * l40;
  const double z = a - b * std::log10(temperature_c + kKelvin);
  return std::pow(10.0, std::pow(10.0, z)) - 0.7;
}

double alpha_at(const std::vector<std::pair<double, double>> &table, double t)
{
  if (table.size() < 2 || !(t >= table.front().first && t <= table.back().first))
    throw LubricantError("temperature " + std::to_string(t) +
                         " C is outside the range of the lubricant's alpha table (" +
                         (table.empty() ? std::string("empty")
                                        : std::to_string(table.front().first) + " to " +
                                              std::to_string(table.back().first) + " C") +
                         "; alpha is not extrapolated)");
  std::size_t k = 1;
  while (k + 1 < table.size() && t > table[k].first) ++k;
  const auto &[t0, a0] = table[k - 1];
  const auto &[t1, a1] = table[k];
  if (t == t0) return a0;
  if (t == t1) return a1;
  return a0 * std::exp(std::log(a1 / a0) * (t - t0) / (t1 - t0));
}

namespace {

double dynamic_viscosity(const Lubricant &lub, double t)
{
  return walther_viscosity(lub.nu40, lub.nu100, t) * 1e-6 *
         (lub.rho15 * (1.0 - lub.expansion * (t - 15.0)));
}

}  // namespace

LubricantState state_at(const Lubricant &lub, double t)
{
  if (!(t >= -40.0 && t <= 200.0))
    throw LubricantError("temperature: expected -40 to 200 C, got " + std::to_string(t));
  LubricantState s;
  s.temperature = t;
  s.nu = walther_viscosity(lub.nu40, lub.nu100, t) * 1e-6;
  s.rho = lub.rho15 * (1.0 - lub.expansion * (t - 15.0));
  s.eta = s.nu * s.rho;
  s.alpha = lub.alpha_table.empty() ? lub.alpha : alpha_at(lub.alpha_table, t);
  s.eps_r = lub.eps_r + lub.eps_slope * (t - lub.tref);
  // Walden's rule: ionic conduction, the conductivity inversely proportional to the viscosity.
  s.resistivity = std::isnan(lub.resistivity_tref)
                      ? lub.resistivity
                      : lub.resistivity * s.eta / dynamic_viscosity(lub, lub.resistivity_tref);
  s.breakdown = lub.breakdown;
  if (!(s.nu > 0.0) || !(s.rho > 0.0) || !(s.eps_r >= 1.0))
    throw LubricantError("lubricant " + lub.name + " at " + std::to_string(t) +
                         " C: viscosity, density or permittivity out of range (eps_r " +
                         std::to_string(s.eps_r) + ")");
  return s;
}

Lubricant read_lubricant_file(const std::string &path, const std::string &name)
{
  std::ifstream in(path);
  if (!in) throw LubricantError("lubricant file '" + path + "' cannot be read");
  std::map<std::string, double> v;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string body = line.substr(0, line.find('#'));
    std::istringstream ss(body);
    std::string word, key, style, value, extra;
    if (!(ss >> word)) continue;  // blank or comment
    const std::string where = path + ":" + std::to_string(n);
    if (word != "variable" || !(ss >> key >> style >> value) || style != "index" || (ss >> extra))
      throw LubricantError(where + ": expected 'variable NAME index VALUE  # source'");
    char *end = nullptr;
    const double x = std::strtod(value.c_str(), &end);
    if (end == value.c_str() || *end != '\0' || !std::isfinite(x))
      throw LubricantError(where + ": " + key + " expects a number, got '" + value + "'");
    v[key] = x;
  }
  Lubricant lub;
  lub.name = name;
  auto get = [&](const char *key, bool positive) {
    const auto it = v.find(key);
    if (it == v.end()) throw LubricantError(path + ": " + key + " is missing");
    if (positive && !(it->second > 0.0))
      throw LubricantError(path + ": " + key + " must be > 0, got " + std::to_string(it->second));
    return it->second;
  };
  lub.nu40 = get("nu40", true);
  lub.nu100 = get("nu100", true);
  lub.rho15 = get("rho15", true);
  lub.expansion = get("expansion", false);
  // alpha: constant, or the table alpha_T1, alpha_1, alpha_T2, alpha_2[, alpha_T3, alpha_3].
  for (int k = 1; k <= 3; ++k) {
    const std::string tk = "alpha_T" + std::to_string(k), ak = "alpha_" + std::to_string(k);
    if (!v.count(tk) && !v.count(ak)) break;
    const double tv = get(tk.c_str(), false), av = get(ak.c_str(), true);
    if (!lub.alpha_table.empty() && !(tv > lub.alpha_table.back().first))
      throw LubricantError(path + ": expected " + tk + " above alpha_T" + std::to_string(k - 1));
    lub.alpha_table.emplace_back(tv, av);
  }
  if (v.count("alpha_T4") || v.count("alpha_4"))
    throw LubricantError(path + ": the alpha table has at most 3 points (alpha_T1..alpha_T3)");
  if (lub.alpha_table.size() == 1)
    throw LubricantError(path + ": the alpha table needs at least 2 points (alpha_T2, alpha_2)");
  if (lub.alpha_table.empty())
    lub.alpha = get("alpha", true);
  else if (v.count("alpha"))
    throw LubricantError(path + ": give alpha or the table alpha_T1, alpha_1, ..., not both");
  lub.eps_r = get("eps_r", true);
  lub.eps_slope = get("eps_slope", false);
  lub.tref = get("tref", false);
  lub.resistivity = get("resistivity", true);
  if (v.count("resistivity_tref")) {
    lub.resistivity_tref = get("resistivity_tref", false);
    if (!(lub.resistivity_tref >= -40.0 && lub.resistivity_tref <= 200.0))
      throw LubricantError(path + ": resistivity_tref: expected -40 to 200 C");
  }
  if (v.count("breakdown")) lub.breakdown = get("breakdown", true);
  if (!(lub.nu100 < lub.nu40) || !(lub.nu100 >= 2.0))
    throw LubricantError(path + ": expected nu40 > nu100 >= 2 mm^2/s (Walther's range), got " +
                         std::to_string(lub.nu40) + " and " + std::to_string(lub.nu100));
  if (!(lub.expansion >= 0.0) || !(lub.eps_r >= 1.0))
    throw LubricantError(path + ": expected expansion >= 0 and eps_r >= 1");
  // The ranges the laws hold in (doc/lubricant_catalog.md): beyond them the film, the
  // capacitance and the impedance come out as overflows and NaN, not as a lubricant.
  auto within = [&path](const char *key, double x, double lo, double hi, const char *what) {
    if (!(x >= lo && x <= hi)) {
      char msg[512];
      std::snprintf(msg, sizeof msg, "%s: %s = %g is outside %s: expected %g to %g", path.c_str(),
                    key, x, what, lo, hi);
      throw LubricantError(msg);
    }
  };
  within("nu40", lub.nu40, 2.0, 2e7, "Walther's range of kinematic viscosity (ASTM D341, mm^2/s)");
  within("nu100", lub.nu100, 2.0, 2e7,
         "Walther's range of kinematic viscosity (ASTM D341, mm^2/s)");
  within("rho15", lub.rho15, 500.0, 2500.0, "the densities of liquid lubricants (kg/m^3)");
  within("expansion", lub.expansion, 0.0, 2e-3, "the thermal expansion of liquids (1/K)");
  const char *alpha_range = "the pressure-viscosity coefficients of lubricants (1/Pa)";
  if (lub.alpha_table.empty()) within("alpha", lub.alpha, 1e-10, 1e-7, alpha_range);
  for (std::size_t k = 0; k < lub.alpha_table.size(); ++k)
    within(("alpha_" + std::to_string(k + 1)).c_str(), lub.alpha_table[k].second, 1e-10, 1e-7,
           alpha_range);
  within("eps_r", lub.eps_r, 1.0, 100.0, "relative permittivities (1 to 100)");
  within("eps_slope", lub.eps_slope, -0.1, 0.1, "permittivity slopes (1/K)");
  within("tref", lub.tref, -40.0, 200.0, "the temperature range of the laws (C)");
  within("resistivity", lub.resistivity, 1e-8, 1e20, "resistivities (ohm m)");
  if (lub.breakdown > 0) within("breakdown", lub.breakdown, 1e3, 1e10, "breakdown fields (V/m)");
  return lub;
}

std::string lubricant_path(const std::string &s, const std::string &dir)
{
  if (s.find('/') != std::string::npos) return s;
  const std::vector<std::string> names = names_in(dir);
  if (is_name(s) && std::find(names.begin(), names.end(), s) != names.end()) return dir + "/" + s;
  std::string known;
  for (const auto &n : names) known += (known.empty() ? "" : " ") + n;
  throw LubricantError("lubricant '" + s + "' is not in the catalog " + dir + " (known: " +
                       (known.empty() ? "(none)" : known) + "; or give a path with a '/')");
}

std::string default_lubricant_dir()
{
  const char *env = std::getenv("OHMDEM_LUBRICANTS");
  if (env && *env) return env;
  std::string exe(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  if (n > 0) {
    exe.resize(static_cast<std::size_t>(n));
    const std::string dir = exe.substr(0, exe.rfind('/')) + "/" + OHMDEM_INSTALLED_LUBRICANTS;
    if (is_folder(dir)) return dir;
  }
  return OHMDEM_LUBRICANTS_DIR;
}

}  // namespace ohmdem::lubrication
