// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/cage: a rigid cage with N pockets, one rotational
   degree of freedom, driven by the balls.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(bearing/cage,FixBearingCage)
// clang-format on

#else

#ifndef LMP_FIX_BEARING_CAGE_H
#define LMP_FIX_BEARING_CAGE_H

#include <memory>
#include <vector>

#include "BEARING/fix_bearing_body.h"
#include "common/ordered_reduce.h"

namespace ohmdem {
struct CageContactModel;
}

namespace LAMMPS_NS {

class FixBearingCage : public FixBearingBody {
 public:
  FixBearingCage(class LAMMPS *, int, char **);
  ~FixBearingCage() override;
  void post_create() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double compute_vector(int) override;
  double memory_usage() override;
  // "cage_critical_step" (s) and "cage_mass" (kg): for the races' runaway message.
  void *extract(const char *name, int &dim) override;

  double angle() const { return angle_; }
  double omega() const { return omega_; }
  int pockets() const { return npockets_; }
  double pitch_radius() const { return pitch_radius_; }
  void centre(double &x, double &y) const
  {
    x = cx_;
    y = cy_;
  }
  ohmdem::BearingSurface surface() const override;
  // model 3d (fix_bearing_cage_3d.cpp): cylindrical pockets, the cage free along its axis.
  bool three_d() const override { return three_d_; }

 private:
  void parse(int narg, char **arg);
  void build_model();
  void assign_pockets();

  int npockets_ = 0;
  double pitch_radius_ = 0, clearance_ = 0;
  int cage_type_ = 0;
  double mass_ = 0, inertia_ = 0, drag_ = 0;
  double cx_ = 0, cy_ = 0;
  double angle0_ = 0;          // pocket 0 at this angle when the cage angle is 0
  bool warned_empty_ = false;  // the empty-pockets warning, once per fix
  // cos, sin of 2 pi k / npockets: pocket k's direction is the cage rotation applied to it,
  // so a step needs one sincos, not one per ball.
  std::vector<double> pocket_cos_, pocket_sin_;

  // cage state, identical on all ranks, written to restart
  double angle_ = 0, omega_ = 0;

  // last force evaluation
  double torque_ = 0, sum_fn_ = 0, max_fn_ = 0;
  int nmasked_ = 0;        // ball contacts with a broken cage bar (fix bearing/defect cage)
  double ball_orbit_ = 0;  // mean orbital angular speed of the balls about the axis
  bool wall_broken(const ohmdem::BearingSurface &surface, int pocket, int side) const;
  int ncontacts_ = 0;
  // Per ball: pocket force, torque on the cage, orbital angular speed about the axis.
  // Members so that their memory is reused from step to step.
  std::vector<ohmdem::TaggedValues<3> > mine_;
  ohmdem::OrderedGather<3> gather_;

  std::unique_ptr<ohmdem::CageContactModel> model_;
  // sqrt(mu/k) of a ball on a pocket wall at 1 N, mu the reduced mass of the cage (as a mass at
  // the pitch radius) and the ball: its critical step, set with the model
  double critical_step_ = 0;

  // --- model 3d (fix_bearing_cage_3d.cpp)
  void post_force_3d();
  void axial_half_kick_3d(double dt);
  void reapply_axial_forces_3d();
  // The members a restart record holds, in file order, for a RestartWriter or RestartReader
  // (support/global_restart.h); model 3d adds its axial state and the marker 3.
  template <class Visit> void restart_fields(Visit &record);
  bool three_d_ = false;
  double cz_ = 0, vz_ = 0;  // the cage's axial position and velocity (m, m/s)
  double axial_ = 0;        // the balls' axial force on it (N)
  std::vector<ohmdem::TaggedValues<1> > mine_axial_;  // per touching ball: its axial force
  ohmdem::OrderedGather<1> gather_axial_;
};

}  // namespace LAMMPS_NS

#endif
#endif
