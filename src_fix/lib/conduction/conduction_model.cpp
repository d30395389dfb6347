// SPDX-License-Identifier: GPL-2.0-or-later
// The composition table of the conduction model and the run-constant part of the bearing's
// closed form; see conduction_model.h.
#include "conduction/conduction_model.h"

namespace ohmdem {

const std::vector<ModelEntry> &model_table()
{
  static const std::vector<ModelEntry> table = {
      {"eq1", {BulkLaw::Eq1, ConstrictionLaw::None}},    // the paper
      {"holm", {BulkLaw::None, ConstrictionLaw::Holm}},  // particles equipotential
      {"eq1+holm", {BulkLaw::Eq1, ConstrictionLaw::Holm}},
  };
  return table;
}

bool find_model(const std::string &name, ConductionModel &model)
{
  for (const ModelEntry &e : model_table())
    if (name == e.name) {
      model = e.model;
      return true;
    }
  return false;
}

std::string model_names()
{
  const auto &t = model_table();
  std::string s;
  for (std::size_t k = 0; k < t.size(); ++k)
    s += (k == 0 ? "" : k + 1 == t.size() ? " or " : ", ") + std::string(t[k].name);
  return s;
}

BallBetweenRaces::BallBetweenRaces(const ConductionModel &model, const HertzContact &hi,
                                   const HertzContact &lo, double gamma_hi, double gamma_lo,
                                   const std::vector<double> &gamma_type)
    : model_(model),
      hi_(&hi),
      lo_(&lo),
      gamma_hi_(gamma_hi),
      gamma_lo_(gamma_lo),
      races_conduct_(gamma_hi > 0.0 && gamma_lo > 0.0)
{
  // eq. 1 with S_k = area_k(1 N) * fn_k^(2/3) and 1/(2V) = 3/(8 pi r^3).
  eq1_coef_ = hi.ellipse(1.0).area * lo.ellipse(1.0).area * 3.0 / (8.0 * kPi);
  holm_hi_ = holm_factor(hi.ellipticity());
  holm_lo_ = holm_factor(lo.ellipticity());
  const double a_hi = hi.ellipse(1.0).a, a_lo = lo.ellipse(1.0).a;
  holm_per_type_.assign(2 * gamma_type.size(), 0.0);
  for (std::size_t t = 1; t < gamma_type.size(); ++t) {
    holm_per_type_[2 * t] = mixed_resistivity(gamma_type[t], gamma_hi) * holm_hi_ / a_hi;
    holm_per_type_[2 * t + 1] = mixed_resistivity(gamma_type[t], gamma_lo) * holm_lo_ / a_lo;
  }
}

double BallBetweenRaces::general(double gamma, double r, double fn_hi, double fn_lo,
                                 const double u[3], const double w[3]) const
{
  const auto eh = hi_->ellipse(fn_hi), el = lo_->ellipse(fn_lo);
  double resistance = 0.0;
  if (model_.has_bulk()) {
    const double g = eq1_conductance_between(gamma, eh.area, el.area, sphere_volume(r), u, w, r);
    resistance += g > 0.0 ? 1.0 / g : std::numeric_limits<double>::infinity();
  }
  if (model_.has_constriction() && races_conduct_) {
    resistance += mixed_resistivity(gamma, gamma_hi_) * holm_hi_ / eh.a;
    resistance += mixed_resistivity(gamma, gamma_lo_) * holm_lo_ / el.a;
  }
  return 1.0 / resistance;
}

}  // namespace ohmdem
