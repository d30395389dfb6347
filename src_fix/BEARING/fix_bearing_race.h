// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - electrical signatures of bearing defects, a LIGGGHTS extension.
   fix bearing/race: an analytic bearing ring with a toroidal groove.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(bearing/race,FixBearingRace)
// clang-format on

#else

#ifndef LMP_FIX_BEARING_RACE_H
#define LMP_FIX_BEARING_RACE_H

#include <memory>
#include <vector>

#include "BEARING/fix_bearing_body.h"
#include "common/ordered_reduce.h"
#include "support/race_contact_view.h"

namespace ohmdem {
struct RaceContactModel;
class StyleArgs;
}  // namespace ohmdem

namespace LAMMPS_NS {

class FixBearingRace : public FixBearingBody {
 public:
  FixBearingRace(class LAMMPS *, int, char **);
  ~FixBearingRace() override;
  void post_create() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  void reset_dt() override {}
  void write_restart(FILE *) override;
  void restart(char *) override;
  double compute_vector(int) override;
  double memory_usage() override;

  // For the electrical computes: the contact of local atom i with this race, valid after
  // this step's forces.
  ohmdem::RaceContactView contact_of(int i) const { return ohmdem::RaceContactView(array_atom[i]); }
  const ohmdem::RaceContactModel &contact_model() const { return *model_; }
  bool is_inner() const { return inner_; }
  double groove() const { return groove_; }  // groove radius (m)
  double current_radius() const;
  void centre(double &x, double &y) const
  {
    x = cx_;
    y = cy_;
  }
  double angle() const { return angle_; }
  ohmdem::BearingSurface surface() const override;
  int race_type() const { return race_type_; }

 private:
  enum class Load { None, Force, Fixed, Settle, Radial };

  void parse(int narg, char **arg);
  void check_load(ohmdem::StyleArgs &a, bool have_force, bool have_settle, bool have_interference,
                  double dir_x, double dir_y);
  void build_model();
  double target_omega(double t) const;
  void ring_half_kick(double dt);
  void ring_acceleration(double &ax, double &ay) const;

  // --- arguments
  bool inner_ = true;
  double radius_ = 0, groove_ = 0;
  int race_type_ = 0;
  double omega_ = 0, ramp_ = 0;
  double omega_start_ = 0;  // the ramp goes from omega_start_ to omega_ (run-up or coast-down)
  // omega v_NAME / force v_NAME: equal-style variables evaluated at the start of each step
  std::string omega_var_, force_var_;
  int omega_ivar_ = -1, force_ivar_ = -1;
  double omega_now_ = 0;  // the speed variable's value of this step
  void find_variables();
  void evaluate_variables();
  Load load_ = Load::None;
  double load_force_ = 0;             // force / settle: isotropic F (N)
  double load_fx_ = 0, load_fy_ = 0;  // radial load vector (N)
  double dir_ux_ = 0, dir_uy_ = -1;   // unit load direction (outputs along/across it)
  double interference_ = 0;           // fixed: imposed radial interference (m)
  double settle_time_ = 0;            // settle: force control until this time (s)
  double ring_mass_ = 0, ring_damp_ = 0;

  // --- ring state (identical on all ranks; written to restart)
  double time_ = 0;                             // time since the fix started acting (s)
  double angle_ = 0;                            // ring rotation (rad)
  double u_ = 0, u_dot_ = 0;                    // radial interference toward the balls (m)
  double cx_ = 0, cy_ = 0, vcx_ = 0, vcy_ = 0;  // ring centre
  bool frozen_ = false;                         // settle mode: the radius is held since settle_time

  // --- reactions of the last force evaluation (deterministic sums, see ordered_reduce.h)
  double sum_fn_ = 0, torque_ = 0, fx_ = 0, fy_ = 0, max_fn_ = 0;
  int ncontacts_ = 0;
  int nmasked_ = 0;  // contacts whose point lies in a defect zone (no current)
  double defect_recess(int i, const ohmdem::BearingSurface &surface, bool &in_zone) const;
  // Per touching ball: force on the ball x, y, normal force, torque on the race. Members so
  // that their memory is reused from step to step.
  std::vector<ohmdem::TaggedValues<4> > mine_;
  ohmdem::OrderedGather<4> gather_;

  std::unique_ptr<ohmdem::RaceContactModel> model_;
  double ball_radius_ = 0;
  double ball_mass_ = 0;       // largest ball mass of the group (kg)
  double mean_fn_ = 0;         // running mean load per touching ball (N), for messages
  long long sound_steps_ = 0;  // steps that passed the runaway check
  void check_runaway();        // error->all when the contacts ran away (contact/runaway.h)
  void check_load_in_elastic_range();
  void check_restart_geometry();
  int ball_type_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
