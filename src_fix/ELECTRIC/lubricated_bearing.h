// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant: the bearing's impedance at the excitation
// frequency from this step's race contacts, ball and ring velocities. Each ball-race contact
// gets one record (contact()); the records feed the closed form (each ball its two contacts
// in series, the balls in parallel), the general network (lubricated_network.*), the AC
// netlist and the local array. The physics is in lib/lubrication (doc/methods/lubricated_contact.md).
// Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_LUBRICATED_BEARING_H
#define OHMDEM_STYLE_LUBRICATED_BEARING_H

#include <complex>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ELECTRIC/resistance_context.h"
#include "common/ordered_reduce.h"
#include "conduction/conduction_model.h"
#include "lubrication/bearing_kernels.h"
#include "lubrication/contact_admittance.h"
#include "lubrication/lubricant.h"
#include "lubrication/pit_gap.h"
#include "lubrication/race_admittance.h"
#include "pointers.h"
#include "support/bearing_surface.h"
#include "support/race_contact_view.h"

namespace LAMMPS_NS {

// A race pit in the contact's rolling coordinate x (from the contact point along the raceway):
// the pit's centre is at -offset.
inline ohmdem::lubrication::PitStrip pit_strip(const ohmdem::PitView &p)
{
  return {-p.offset - 0.5 * p.width, -p.offset + 0.5 * p.width, p.depth, p.ball_radius};
}

// The keywords of compute network/resistance that concern the lubricant.
struct LubricationSettings {
  std::string lubricant = "none";  // a catalog name, a path, or none
  double temperature = 40.0;       // C
  double roughness = -1.0;         // composite RMS roughness (m); required with a lubricant
  double fexc = -1.0;              // excitation frequency (Hz); required with a lubricant
  double wetted = -1.0;            // wetted radius around a contact (m); required
  double excitation = 1.0;         // voltage amplitude across the bearing (V)
  double breakdown = 0.0;          // breakdown field of the film (V/m); 0: no breakdown
  bool breakdown_file = false;     // `breakdown lubricant`: the lubricant file's field instead
  bool network = false;            // the general network (keyword closedform no)
  // The per-step arithmetic (keyword kernel): lanes (the default) or plain, the same bits
  // (lib/lubrication/bearing_kernels.h).
  ohmdem::lubrication::BearingKernel kernel = ohmdem::lubrication::BearingKernel::lanes;
  bool on() const { return lubricant != "none"; }
};

// A race's constants that are the oil's and the settings' (both models' RaceInput).
inline void set_oil(ohmdem::lubrication::RaceInput &in, const LubricationSettings &settings,
                    const ohmdem::lubrication::LubricantState &oil)
{
  in.eta = oil.eta;
  in.alpha = oil.alpha;
  in.sigma = settings.roughness;
  in.r_wet = settings.wetted;
  in.eps_r = oil.eps_r;
  in.resistivity = oil.resistivity;
}

// The global outputs 9-15 of the compute.
struct LubricatedResult {
  double z_abs = 0, z_phase = 0, c_parallel = 0, r_parallel = 0;
  double hmin_inner = 0, hmin_outer = 0, lambda_min = 0;
  static constexpr int kSize = 7;
  std::complex<double> v_high{0.0, 0.0};  // the high electrode's phasor Z I (V)
};

// One ball-race contact of the step, on the process owning the ball.
struct LubricatedContact {
  std::int64_t tag = 0;
  int side = 0;         // 0: the high electrode's race, 1: the low one's
  bool loaded = false;  // pressed: a film; else the gap to the race (h_central = h_min = gap)
  std::complex<double> y{0.0, 0.0};             // G + j omega C (S)
  double h_central = 0, h_min = 0, lambda = 0;  // film (m) and h_min / roughness
  double c = 0, g = 0;                          // capacitance (F), conductance (S)
};

class FixBearingRace;
class LubricatedNetwork;

class LubricatedBearing : protected Pointers {
 public:
  // Reads the lubricant (throws LubricantError with the message for the user).
  LubricatedBearing(LAMMPS *lmp, const LubricationSettings &settings);
  const ohmdem::lubrication::LubricantState &state() const { return state_; }
  const std::string &path() const { return path_; }
  // init(): both electrodes must be races (checked by the compute). The geometry is read at
  // the first evaluation of the run.
  void init(const ResistanceContext &context);
  ~LubricatedBearing() override;
  // Collective: this step's admittance of the bearing; `gather` (an export step) also gathers
  // the records of all processes (network()) when the closed form runs. g_dry: the dry closed
  // form's conductance of this step per local atom (NaN where it has none), or null. Its
  // impedance and minima are read by impedance() and minima().
  void evaluate(const ResistanceContext &context, bool gather = false,
                const double *g_dry = nullptr);
  // Collective: the last evaluation's smallest films and lambda over all processes (outputs
  // 13-15) into out. Apart from evaluate(): a step where nothing reads them has no reduction.
  void minima(LubricatedResult &out) const;
  // The last evaluation's impedance (outputs 9-12) and the high electrode's phasor into out,
  // from its admittance. Apart from evaluate() too: a step where nothing reads them pays
  // nothing (one complex division, a hypot and an atan2, ~0.3k instructions).
  void impedance(LubricatedResult &out) const;
  // This process's records of the last evaluation (two per ball, high race first), built at
  // the first call after it.
  const std::vector<LubricatedContact> &contacts() const;
  const LubricatedNetwork &network() const { return *network_; }
  double omega() const { return omega_; }

 private:
  void set_geometry(const ResistanceContext &context);
  // evaluate() with the settings' kernel (lib/lubrication/bearing_kernels.h).
  template <class Kernel>
  void evaluate_with(const ResistanceContext &context, bool gather, const double *g_dry);
  // The end of an evaluation, both models: the balls from their contacts (breakdown, series),
  // the bearing's admittance (the network or the ordered sum), the films' minima.
  template <class Kernel>
  void combine(const ResistanceContext &context, bool gather, const double hmin[2],
               double lambda_min);
  // Ball i's contact with race `side` (its row `view`, its entrainment speed): a race the ball
  // does not press gets an idle record (the gap's capacitance), else the contact's inputs go
  // into the race's batch (g_ball: the ball's dry, metallic conductance between its two
  // races). Returns its index in the batch, or -1 - its index in idle_.
  int collect(int i, int side, double g_ball, const ohmdem::RaceContactView &view, double speed);
  void build_records() const;  // contacts_ from balls_in_, films_ and idle_
  // A pressed contact's record from its admittance.
  void fill(const ohmdem::lubrication::ContactAdmittance &c, LubricatedContact &out) const;
  // A ball's two records under the excitation: a film whose voltage exceeds the breakdown
  // field times its gap conducts through its metal (doc/methods/lubricated_contact.md).
  void break_down(LubricatedContact pair[2],
                  const ohmdem::lubrication::ContactAdmittance film[2]) const;
  double ball_dry_conductance(const ResistanceContext &context, int i);
  // Model 3d races (lubricated_bearing_3d.cpp): each contact its own effective radii, ellipse
  // and entrainment speed at its contact angle (FixBearingRace::film_geometry_3d), its
  // admittance from lub::contact_admittance; the balls, breakdown and network as in model 2d
  // (combine()).
  void evaluate_3d(const ResistanceContext &context, bool gather, const double *g_dry);
  // Model 3d: ball i's dry (metallic) conductance between the races where the closed form has
  // none this step (the general network, an export step, a ball on one race).
  double ball_dry_conductance_3d(const ResistanceContext &context, int i) const;

  LubricationSettings settings_;
  double omega_ = 0;  // 2 pi fexc
  bool geometry_ready_ = false;
  std::string path_;
  ohmdem::lubrication::LubricantState state_;
  ohmdem::BallBetweenRaces dry_;  // the dry conductance of a ball (the metallic path)
  // Per side (0 high, 1 low): the race, its contacts' constants, 0 inner / 1 outer.
  const FixBearingRace *race_[2] = {nullptr, nullptr};
  ohmdem::lubrication::RaceFrame motion_[2];  // this step's, set by evaluate()
  double local_min_[3] = {0, 0, 0};  // this process's h_min inner, outer, lambda (evaluate())
  std::complex<double> y_bearing_{0.0, 0.0};  // the bearing's admittance (evaluate())
  double current_ = 0;                        // the current of that evaluation (A)
  ohmdem::lubrication::RaceAdmittance film_[2];
  int inner_[2] = {0, 1};
  // Scratch of evaluate(), per side: the pressed contacts' inputs and admittances, ball order.
  ohmdem::lubrication::ContactBatch batch_[2];
  std::vector<ohmdem::lubrication::ContactAdmittance> films_[2];
  // The pressed contacts near a race pit: corrected after their batch (pit_contact.h).
  struct PitFix {
    int side = 0;
    std::size_t index = 0;  // in batch_[side] and films_[side]
    double fn = 0, rest = 0;
    ohmdem::PitView pit;
  };
  std::vector<PitFix> pit_fixes_;
  ohmdem::PitView pit_;  // collect()'s: a member, not a fresh zeroed one per contact
  // Per local ball of the last evaluation: its tag and, per side, its index in films_[side]
  // (>= 0) or -1 - its index in idle_ (a race it does not press).
  struct BallRefs {
    std::int64_t tag = 0;
    int ref[2] = {0, 0};
  };
  std::vector<BallRefs> balls_in_;
  std::vector<LubricatedContact> idle_;
  mutable std::vector<LubricatedContact> contacts_;  // the records (build_records())
  mutable bool records_ready_ = false;
  std::vector<ohmdem::TaggedValues<2>> balls_;  // Re Y, Im Y per ball
  ohmdem::OrderedGather<2> gather_;
  std::unique_ptr<LubricatedNetwork> network_;
};

}  // namespace LAMMPS_NS

#endif
