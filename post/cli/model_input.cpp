// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/model_input.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/text_scan.h"

namespace ohmdem::post::cli {

void read_curve(const std::string &path, const std::string &flag, const std::string &value,
                std::vector<double> &sizes, std::vector<double> &values)
{
  std::ifstream in(path);
  if (!in) throw Error("diagnose: " + flag + " " + path + ": cannot open the file");
  const std::string form = "'SIZE_DEG " + value + "'";
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double sz = 0, ar = 0;
    if (!(ls >> sz >> ar) || !std::isfinite(sz) || !std::isfinite(ar))
      throw Error("diagnose: " + flag + " " + path + ": expected lines " + form + ", got '" + line +
                  "'");
    if (!sizes.empty() && (sz <= sizes.back() || ar <= values.back()))
      throw Error("diagnose: " + flag + " " + path + ": sizes and " +
                  (value == "AREA_S"    ? "areas"
                   : value == "WIDTH_S" ? "widths"
                                        : "energies") +
                  " must both increase from line to line");
    sizes.push_back(sz);
    values.push_back(ar);
  }
  if (sizes.size() < 2)
    throw Error("diagnose: " + flag + " " + path + ": needs at least two lines " + form);
}

namespace {

const char *const kForms =
    "a bank of pulse templates (first line '# ohmdem-post pulse template bank', "
    "studies/template_bank.py) or a curve whose first line names its feature ('... : size_deg, "
    "fixed-window pulse area / level (s)', '... entry-to-exit width (s)' or '... pass energy "
    "(V^2 s)', studies/sizing.py)";

// The header's '# model error (...): X; ...' (0 when the header states none).
double header_model_error(const std::string &path)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
    if (line.find("model error") == std::string::npos) continue;
    auto at = line.find("): ");
    at = at == std::string::npos ? line.find("model error:") + 12 : at + 3;
    const std::string v = line.substr(at, line.find(';', at) - at);
    double e = 0;
    if (!parse_double(v, e) || !(e >= 0 && e < 1))
      throw Error("diagnose: --model " + path + ": the model error '" + v +
                  "' is not a relative error in [0, 1)");
    return e;
  }
  return 0;
}

}  // namespace

ModelFiles read_models(const std::vector<std::string> &paths)
{
  ModelFiles m;
  for (const std::string &path : paths) {
    std::ifstream in(path);
    if (!in) throw Error("diagnose: --model " + path + ": cannot open the file");
    std::string first;
    std::getline(in, first);
    auto twice = [&](bool already, const std::string &what) {
      if (already)
        throw Error("diagnose: --model " + path + ": a second " + what +
                    " (give one of each kind)");
    };
    if (first.find("pulse template bank") != std::string::npos) {
      twice(m.bank.has_value(), "bank");
      m.bank = read_template_bank(path);
    } else if (first.find("entry-to-exit width") != std::string::npos) {
      twice(!m.width_s.empty(), "width curve");
      read_curve(path, "--model", "WIDTH_S", m.width_size_deg, m.width_s);
      m.width_rel_error = header_model_error(path);
    } else if (first.find("pulse area") != std::string::npos ||
               first.find("pass energy") != std::string::npos) {
      twice(!m.curve_value.empty(), "curve of the area or the pass energy");
      const bool energy = first.find("pass energy") != std::string::npos;
      read_curve(path, "--model", energy ? "ENERGY_V2S" : "AREA_S", m.curve_size_deg,
                 m.curve_value);
      m.curve_feature = energy ? "pass energy" : "pulse area";
      m.curve_rel_error = header_model_error(path);
    } else {
      throw Error("diagnose: --model " + path + ": not a model file of a known kind; expected " +
                  kForms);
    }
  }
  return m;
}

}  // namespace ohmdem::post::cli
