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
#include "contact/hertz_contact.h"
#include "support/race_contact_view.h"

namespace ohmdem {
struct RaceContactModel;
struct RaceContactModel3d;
struct RingMotion3d;
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
  ohmdem::RaceContactView contact_of(int i) const
  {
    return ohmdem::RaceContactView(array_atom[i], three_d());
  }
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

  // model 3d (fix_bearing_race_3d.cpp): the race is a torus, contact angles come from the
  // geometry, a ring under load radial is free in space.
  bool three_d() const override { return settings_.model3d.on; }
  // The ellipse of ball i's contact with this race in the area model `model`: model 3d at its
  // contact angle of this step; model 2d the contact model's (contact_model()).
  ohmdem::ContactEllipse ellipse_of(int i, ohmdem::AreaModel model) const;
  // Model 3d, for the lubricated contact: ball i's contact with this race as the film sees it
  // (its effective radii at the contact angle, the exact ellipse, the entrainment speed), or
  // the gap to it when the ball does not press it; the ellipse in the compute's area model.
  struct FilmGeometry {
    bool pressed = false;
    double fn = 0;          // N
    double rx = 0, ry = 0;  // 1/A, 1/B at the contact angle (m)
    double a = 0, b = 0;    // semi-axes, a across the groove (m)
    double speed = 0;       // mean entrainment speed (m/s)
    double gap = 0;         // not pressed: the gap to the groove along the contact line (m)
    double e_prime = 0;     // E' = 2 E* (Pa)
  };
  FilmGeometry film_geometry_3d(int i, ohmdem::AreaModel model) const;

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

  // --- model 3d (fix_bearing_race_3d.cpp): the ring as a rigid body in space
  static int state_columns_3d();  // the per-ball state's columns in model 3d
  void build_model_3d();
  ohmdem::RingMotion3d ring_motion_3d() const;
  void post_force_3d();
  void initial_integrate_3d();
  void ring_half_kick_3d(double dt);
  void housing_force(double &hx, double &hy) const;  // model 3d, outer ring on its housing
  double compute_vector_3d(int n);
  // The members a restart record holds, in file order, for a RestartWriter or RestartReader
  // (support/global_restart.h); `side` is the record's race side and model (side_code()).
  template <class Visit> void restart_fields(Visit &record, double &side);
  double side_code() const { return (three_d() ? 2.0 : 0.0) + (settings_.inner ? 1.0 : 0.0); }
  bool reapply_restored_forces_3d();
  // The defects' recess under ball i's contact at contact angle alpha (rad), as defect_recess.
  double defect_recess_3d(int i, double alpha, bool &in_zone) const;
  // Ball i's contact angle with this ring in its position `ring` (rad, before the recess, in
  // the ring's frame): where across the groove a defect meets the contact.
  double contact_angle_3d(int i, const ohmdem::RingMotion3d &ring) const;
  std::unique_ptr<ohmdem::RaceContactModel3d> model3d_;
  const FixBearingRace *other_race_ = nullptr;       // the bearing's other race (build_model_3d)
  double cz_ = 0, vcz_ = 0;                          // axial position and velocity of the centre
  double tilt_[2] = {0, 0}, tilt_rate_[2] = {0, 0};  // the axis' tilt (rotation vector x, y)
  double tilt_inertia_ = 0, tilt_damp_ = 0;          // kg m^2, N m s
  double fz_ = 0, moment_[2] = {0, 0};     // balls' axial force and tilting moment (last step)
  double radial_sum_ = 0;                  // sum of Q cos(alpha): what the radius' u feels
  double alpha_mean_ = 0, alpha_max_ = 0;  // |contact angle| over the contacts (degrees)
  std::vector<ohmdem::TaggedValues<11> > mine3d_;
  ohmdem::OrderedGather<11> gather3d_;
};

}  // namespace LAMMPS_NS

#endif
#endif
