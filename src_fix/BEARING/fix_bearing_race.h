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
#include <string>
#include <vector>

#include "BEARING/fix_bearing_body.h"
#include "BEARING/race_checks.h"
#include "BEARING/race_settings.h"
#include "BEARING/race_variables.h"
#include "common/ordered_reduce.h"
#include "support/race_contact_view.h"

namespace ohmdem {
struct RaceContactModel;
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
  // How far the surface under that contact falls away (m): the recess of the defects' pits
  // (inner, outer or ball) that this step's force used, 0 without defects. A query, so that no
  // published column changes (the positions and surfaces are those of post_force).
  double recess_of(int i) const
  {
    bool in_zone = false;
    return defects_.empty() ? 0.0 : defect_recess(i, defect_surface_, in_zone);
  }
  // For the lubricated gap: the race pit whose zone comes within `reach` (m) of that contact
  // (the first defect with one), and in `rest` the recess of the other defects under it (a
  // ball's pit); false without such a pit, `rest` then recess_of(i).
  bool pit_near(int i, double reach, ohmdem::PitView &pit, double &rest) const
  {
    rest = 0.0;
    return !defects_.empty() && defect_pit(i, reach, pit, rest);  // inline: most runs have none
  }
  bool has_defects() const { return !defects_.empty(); }
  const ohmdem::RaceContactModel &contact_model() const { return *model_; }
  bool is_inner() const { return settings_.inner; }
  double groove() const { return settings_.groove; }  // groove radius (m)
  double current_radius() const;
  void centre(double &x, double &y) const
  {
    x = cx_;
    y = cy_;
  }
  double angle() const { return angle_; }
  // Velocity (m/s) of the ring's material at the point (px, py) on this step: its rotation
  // about its centre plus the centre's velocity (the lubricated contact's entrainment speed).
  void surface_velocity(double px, double py, double &vx, double &vy) const
  {
    const double w = target_omega(time_);
    vx = vcx_ - w * (py - cy_);
    vy = vcy_ + w * (px - cx_);
  }
  // surface_velocity's terms, for a loop over many points: the ring's angular speed and its
  // centre's velocity on this step.
  void rigid_motion(double &w, double &vcx, double &vcy) const
  {
    w = target_omega(time_);
    vcx = vcx_;
    vcy = vcy_;
  }
  ohmdem::BearingSurface surface() const override;
  int race_type() const { return settings_.race_type; }

 private:
  using Load = ohmdem::RaceLoad;

  void build_model();
  void check_fit_between_races();
  double target_omega(double t) const;
  void evaluate_variables();
  void ring_half_kick(double dt);
  void ring_acceleration(double &ax, double &ay) const;
  void check_runaway();  // error->all when the contacts ran away (race_checks.h)

  const ohmdem::RaceSettings settings_;  // the arguments (race_settings.h)
  RaceVariables variables_;              // the equal-style variables omega/force may name
  // --- this step's load and speed (a variable may change them)
  double omega_now_ = 0;              // the speed variable's value of this step
  double load_force_ = 0;             // force / settle / radial: F (N)
  double load_fx_ = 0, load_fy_ = 0;  // radial load vector (N)

  // --- ring state (identical on all ranks; written to restart)
  double time_ = 0;                             // time since the fix started acting (s)
  double angle_ = 0;                            // ring rotation (rad)
  double u_ = 0, u_dot_ = 0;                    // radial interference toward the balls (m)
  double cx_ = 0, cy_ = 0, vcx_ = 0, vcy_ = 0;  // ring centre
  bool frozen_ = false;                         // settle mode: the radius is held since settle_time

  // --- reactions of the last force evaluation (deterministic sums, see ordered_reduce.h)
  double sum_fn_ = 0, torque_ = 0, fx_ = 0, fy_ = 0, max_fn_ = 0;
  int ncontacts_ = 0;
  int loaded_ = 0;  // contacts carrying a load (fn > 0): output 6
  int nmasked_ = 0;  // contacts whose point lies in a defect zone (no current)
  double defect_recess(int i, const ohmdem::BearingSurface &surface, bool &in_zone) const;
  bool defect_pit(int i, double reach, ohmdem::PitView &pit, double &rest) const;  // pit_near
  // Per touching ball: force on the ball x, y, normal force, torque on the race. Members so
  // that their memory is reused from step to step.
  std::vector<ohmdem::TaggedValues<4> > mine_;
  ohmdem::OrderedGather<4> gather_;

  std::unique_ptr<ohmdem::RaceContactModel> model_;
  double ball_radius_ = 0;
  double ball_mass_ = 0;          // largest ball mass of the group (kg)
  ohmdem::RunawayWatch runaway_;  // the steps that passed the runaway check
  // A cage's critical step and mass (fix bearing/cage's extract()), for the runaway's cause.
  const double *cage_step_ = nullptr, *cage_mass_ = nullptr;
  int ball_type_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
