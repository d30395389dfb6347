// SPDX-License-Identifier: GPL-2.0-or-later
// A lubricant of the catalog (inputs/lubricants, doc/lubricant_catalog.md) and its properties
// at a temperature: viscosity by Walther's law (ASTM D341) through the two data-sheet points
// at 40 and 100 C, density with a linear expansion, permittivity with a linear slope; the
// pressure-viscosity coefficient constant or, when the file tabulates it, log-linear in T
// between its points; the resistivity constant or, when the file gives its temperature,
// proportional to the viscosity (Walden's rule). Plain C++.
#ifndef OHMDEM_LUBRICATION_LUBRICANT_H
#define OHMDEM_LUBRICATION_LUBRICANT_H

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ohmdem::lubrication {

// Every failure of the reader; the message names the file and line or the value.
class LubricantError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Lubricant {
  std::string name;
  double nu40 = 0, nu100 = 0;  // kinematic viscosity at 40 and 100 C (mm^2/s)
  double rho15 = 0;            // density at 15 C (kg/m^3)
  double expansion = 0;        // relative density change per K (1/K)
  double alpha = 0;            // pressure-viscosity coefficient (1/Pa); 0 with alpha_table
  double eps_r = 0;            // relative permittivity at tref
  double eps_slope = 0;        // d eps_r / dT (1/K)
  double tref = 40;            // C
  double resistivity = 0;      // ohm m (at resistivity_tref when that is set)
  // Optional (doc/lubricant_catalog.md): alpha at 2-3 temperatures (C, 1/Pa), T ascending;
  // the temperature of `resistivity` (C; NaN: constant resistivity); the dielectric breakdown
  // field (V/m; 0: the file gives none).
  std::vector<std::pair<double, double>> alpha_table;
  double resistivity_tref = std::numeric_limits<double>::quiet_NaN();
  double breakdown = 0;
};

// The lubricant at one temperature.
struct LubricantState {
  double temperature = 0;  // C
  double nu = 0;           // kinematic viscosity (m^2/s)
  double rho = 0;          // density (kg/m^3)
  double eta = 0;          // dynamic viscosity (Pa s)
  double alpha = 0;        // 1/Pa
  double eps_r = 0;
  double resistivity = 0;  // ohm m
  double breakdown = 0;    // V/m, the file's (0: none)
};

// Walther / ASTM D341: log10 log10(nu + 0.7) = A - B log10(T [K]), through (40 C, nu40) and
// (100 C, nu100); nu in mm^2/s. Valid for nu >= 2 mm^2/s (the standard's range without its
// low-viscosity corrections).
double walther_viscosity(double nu40, double nu100, double temperature_c);

// ln alpha linear in T between the table's neighbouring points (exact at each point).
// Throws LubricantError outside the table's range: no extrapolation.
double alpha_at(const std::vector<std::pair<double, double>> &table, double temperature_c);

// Throws LubricantError when the temperature is outside -40..200 C (or the alpha table's
// range) or a property comes out non-positive (a permittivity slope that drives eps_r below 1).
LubricantState state_at(const Lubricant &lub, double temperature_c);

// Parses one file of "variable NAME index VALUE  # source" lines (comments and blank lines
// allowed); every property is required and positive (eps_slope any sign, expansion >= 0),
// alpha either constant or as the table alpha_T1, alpha_1, alpha_T2, alpha_2[, alpha_T3,
// alpha_3]; resistivity_tref and breakdown optional.
Lubricant read_lubricant_file(const std::string &path, const std::string &name);

// A name or a path: a name (letters, digits, '_', '-') is looked up in `dir`; anything with a
// '/' is a file. Throws with the known names when the name is not in the folder.
std::string lubricant_path(const std::string &name_or_path, const std::string &dir);
// The catalog folder: $OHMDEM_LUBRICANTS if set, else the installed one beside this
// executable, else the source tree's inputs/lubricants.
std::string default_lubricant_dir();

}  // namespace ohmdem::lubrication

#endif
