// SPDX-License-Identifier: GPL-2.0-or-later
// The electrical model of a contact network, plain C++ (no LIGGGHTS types): two slots,
//   bulk          the path inside a conducting particle between two of its spots: eq. 1 or none;
//   constriction  the resistance of a contact spot between two bodies: Holm or none;
// composed by a table of named entries (the `model` keyword of compute network/resistance).
// The laws themselves are in conductance_laws.h, each written once. Both evaluations of the
// model use it: BallBetweenRaces below (the bearing closed form, one resistor per ball) and
// build_network() (network_builder.h, the general network). doc/architecture.md.
#ifndef OHMDEM_CONDUCTION_MODEL_H
#define OHMDEM_CONDUCTION_MODEL_H

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/fast_cbrt.h"
#include "conduction/conductance_laws.h"
#include "contact/hertz_contact.h"

namespace ohmdem {

enum class BulkLaw { None, Eq1 };
enum class ConstrictionLaw { None, Holm };

struct ConductionModel {
  BulkLaw bulk = BulkLaw::Eq1;
  ConstrictionLaw constriction = ConstrictionLaw::None;

  bool has_bulk() const { return bulk != BulkLaw::None; }
  bool has_constriction() const { return constriction != ConstrictionLaw::None; }
  // Resistance (Ohm) of a spot of semi-axes a, b between bodies of conductivities gamma_1,
  // gamma_2; 0 without a constriction slot, +inf for a zero-size spot.
  double constriction_resistance(double gamma_1, double gamma_2, double a, double b) const
  {
    if (!has_constriction()) return 0.0;
    return holm_resistance(mixed_resistivity(gamma_1, gamma_2), a, b);
  }
};

// The composition table: one row per value of the `model` keyword.
struct ModelEntry {
  const char *name;
  ConductionModel model;
};
const std::vector<ModelEntry> &model_table();
// The row named `name`; false (model untouched) if there is none.
bool find_model(const std::string &name, ConductionModel &model);
// "eq1, holm or eq1+holm": the names of the table, for error messages.
std::string model_names();

// One ball between two races (the electrodes), its spots on each: the bearing's closed form.
// Everything that depends on the run only (the races' contact geometry at 1 N, their
// conductivities, the conductivity of each atom type) is set once; conductance() then runs
// for every ball at every step, inline, with one or two cube roots and no elliptic integral:
// S = S(1 N) fn^(2/3) and, b/a being fixed, R_Holm = rho * holm_factor / a(1 N) / fn^(1/3).
class BallBetweenRaces {
 public:
  BallBetweenRaces() = default;
  // gamma_type[t]: conductivity of atom type t (S/m), index 0 unused.
  BallBetweenRaces(const ConductionModel &model, const HertzContact &hi, const HertzContact &lo,
                   double gamma_hi, double gamma_lo, const std::vector<double> &gamma_type);

  bool races_conduct() const { return races_conduct_; }

  // What the per-ball evaluation reads, as a small value: copied into a local once per step,
  // it stays in registers through the loop over the balls (members read through `this`
  // would be reloaded after every store of the loop).
  class Kernel {
   public:
    // Conductance (S) of a ball of type t, conductivity gamma > 0 and radius r, with normal
    // forces fn_hi, fn_lo > 0 on the two races and contact vectors u, w (ball centre to the
    // contact points, in the plane: u[2] = w[2] = 0).
    double conductance(int t, double gamma, double r, double fn_hi, double fn_lo, const double u[3],
                       const double w[3]) const
    {
      const double dot = u[0] * w[0] + u[1] * w[1];
      const double norms = std::sqrt((u[0] * u[0] + u[1] * u[1]) * (w[0] * w[0] + w[1] * w[1]));
      const bool facing = dot <= 0.0 && norms > 0.0;
      double conductance;
      if (bulk_only_ && facing) {
        // Spots facing each other (the bearing): S_hi*S_lo needs one cube root; for an obtuse
        // angle 1 - cos(theta) >= 1 and the small-angle clamp of eq. 1 cannot apply.
        const double p = cbrt_fast(fn_hi * fn_lo);
        conductance = gamma * eq1_coef_ * p * p / (r * r * r * (1.0 - dot / norms));
      } else if (races_conduct_ && constriction_ && (facing || !bulk_)) {
        // Holm's constrictions go as 1/a ∝ fn^(-1/3): one cube root per spot.
        const double qh = cbrt_fast(fn_hi), ql = cbrt_fast(fn_lo);
        double resistance = holm_per_type_[2 * t] / qh + holm_per_type_[2 * t + 1] / ql;
        if (bulk_) {
          const double p = qh * ql;
          resistance += r * r * r * (1.0 - dot / norms) / (gamma * eq1_coef_ * p * p);
        }
        conductance = 1.0 / resistance;
      } else {
        conductance = owner_->general(gamma, r, fn_hi, fn_lo, u, w);
      }
      return races_conduct_ ? conductance : 0.0;
    }

   private:
    friend class BallBetweenRaces;
    const BallBetweenRaces *owner_;
    const double *holm_per_type_;
    double eq1_coef_;
    bool bulk_, constriction_, bulk_only_, races_conduct_;
  };
  Kernel kernel() const
  {
    Kernel k;
    k.owner_ = this;
    k.holm_per_type_ = holm_per_type_.data();
    k.eq1_coef_ = eq1_coef_;
    k.bulk_ = model_.has_bulk();
    k.constriction_ = model_.has_constriction();
    k.bulk_only_ = k.bulk_ && !k.constriction_;
    k.races_conduct_ = races_conduct_;
    return k;
  }
  double conductance(int t, double gamma, double r, double fn_hi, double fn_lo, const double u[3],
                     const double w[3]) const
  {
    return kernel().conductance(t, gamma, r, fn_hi, fn_lo, u, w);
  }
  // The constriction resistances (Ohm) of the two spots of a ball of type t with normal
  // forces fn_hi, fn_lo > 0, as conductance() adds them (0 without a constriction slot): the
  // per-contact output splits a ball's series resistance with them.
  void constrictions(int t, double fn_hi, double fn_lo, double &r_hi, double &r_lo) const
  {
    const bool on = races_conduct_ && model_.has_constriction();
    r_hi = on ? holm_per_type_[2 * t] / cbrt_fast(fn_hi) : 0.0;
    r_lo = on ? holm_per_type_[2 * t + 1] / cbrt_fast(fn_lo) : 0.0;
  }

 private:
  // Any angle (the small-angle clamp of eq. 1 may apply): the laws as written.
  double general(double gamma, double r, double fn_hi, double fn_lo, const double u[3],
                 const double w[3]) const;

  ConductionModel model_;
  const HertzContact *hi_ = nullptr, *lo_ = nullptr;
  double gamma_hi_ = 0, gamma_lo_ = 0;
  bool races_conduct_ = false;
  double eq1_coef_ = 0;                // S_hi(1 N) S_lo(1 N) * 3/(8 pi): eq. 1 with 1/(2V)
  double holm_hi_ = 0, holm_lo_ = 0;   // Holm's factors K(e^2)/pi of the two ellipses
  std::vector<double> holm_per_type_;  // [2t], [2t+1]: Holm resistance at 1 N, high / low spot
};

}  // namespace ohmdem

#endif
