// SPDX-License-Identifier: GPL-2.0-or-later
// A lubricant of the catalog (inputs/lubricants, doc/lubricant_catalog.md) and its properties
// at a temperature: viscosity by Walther's law (ASTM D341) through the two data-sheet points
// at 40 and 100 C, density with a linear expansion, permittivity with a linear slope; the
// pressure-viscosity coefficient and the resistivity are taken constant. Plain C++.
#ifndef OHMDEM_LUBRICATION_LUBRICANT_H
#define OHMDEM_LUBRICATION_LUBRICANT_H

#include <stdexcept>
#include <string>

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
  double alpha = 0;            // pressure-viscosity coefficient (1/Pa)
  double eps_r = 0;            // relative permittivity at tref
  double eps_slope = 0;        // d eps_r / dT (1/K)
  double tref = 40;            // C
  double resistivity = 0;      // ohm m
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
};

// Walther / ASTM D341: log10 log10(nu + 0.7) = A - B log10(T [K]), through (40 C, nu40) and
// (100 C, nu100); nu in mm^2/s. Valid for nu >= 2 mm^2/s (the standard's range without its
// low-viscosity corrections).
double walther_viscosity(double nu40, double nu100, double temperature_c);

// Throws LubricantError when the temperature is outside -40..200 C or a property comes out
// non-positive (a permittivity slope that drives eps_r below 1).
LubricantState state_at(const Lubricant &lub, double temperature_c);

// Parses one file of "variable NAME index VALUE  # source" lines (comments and blank lines
// allowed); every property is required and positive (eps_slope any sign, expansion >= 0).
Lubricant read_lubricant_file(const std::string &path, const std::string &name);

// A name or a path: a name (letters, digits, '_', '-') is looked up in `dir`; anything with a
// '/' is a file. Throws with the known names when the name is not in the folder.
std::string lubricant_path(const std::string &name_or_path, const std::string &dir);
// The catalog folder: $OHMDEM_LUBRICANTS if set, else the installed one beside this
// executable, else the source tree's inputs/lubricants.
std::string default_lubricant_dir();

}  // namespace ohmdem::lubrication

#endif
