// SPDX-License-Identifier: GPL-2.0-or-later
// --model FILE[,FILE]: the model data of the record's scene, whatever its kind, told apart by the
// file's header: a bank of pulse templates ('# ohmdem-post pulse template bank', written by
// studies/template_bank.py) or a curve ('# <defect> defect, <load> load, <chain>: size_deg,
// <feature>', written by studies/sizing.py), whose feature is the fixed-window pulse area, the
// pulses' entry-to-exit width or the pass energy, with its model error in the header.
#ifndef OHMDEM_POST_CLI_MODEL_INPUT_H
#define OHMDEM_POST_CLI_MODEL_INPUT_H

#include <optional>
#include <string>
#include <vector>

#include "cli/template_bank_input.h"

namespace ohmdem::post::cli {

struct ModelFiles {
  std::optional<BankFile> bank;
  // the area's or the pass energy's curve (the size methods area and accel-curve read it)
  std::vector<double> curve_size_deg, curve_value;
  std::string curve_feature;  // "pulse area" or "pass energy"
  double curve_rel_error = 0;
  std::vector<double> width_size_deg, width_s;  // the entry-to-exit width's curve
  double width_rel_error = 0;
};

// Throws Error naming --model and the expected forms on a file of no known kind, or two files
// of one kind.
ModelFiles read_models(const std::vector<std::string> &paths);

// Lines "SIZE_DEG VALUE" ('#' comments), at least two, both columns increasing; `flag` and
// `value` (AREA_S, WIDTH_S, ENERGY_V2S) name the option and the second column in the errors.
void read_curve(const std::string &path, const std::string &flag, const std::string &value,
                std::vector<double> &sizes, std::vector<double> &values);

}  // namespace ohmdem::post::cli

#endif
