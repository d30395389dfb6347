// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - the common base of fix bearing/race and fix bearing/cage: a rigid
   body of the bearing with its own degrees of freedom, a contact state per
   ball kept in a fix property/atom, and defects that may act on its contacts.
   Not a style of its own (no FixStyle line).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BEARING_BODY_H
#define LMP_FIX_BEARING_BODY_H

#include <string>
#include <vector>

#include "fix.h"
#include "support/bearing_surface.h"

namespace LAMMPS_NS {

class FixBearingBody : public Fix, public ohmdem::BearingBody {
 public:
  int setmask() override;  // initial_integrate, post_force, final_integrate
  // The bearing axis given by 'centre' (a race's centre moves from it under load radial).
  double axis_x() const { return axis_x_; }
  double axis_y() const { return axis_y_; }
  // The 3D bearing (model 3d) or the planar one: every race and the cage share one model.
  virtual bool three_d() const { return false; }

 protected:
  // vector_size global values and peratom_cols per-atom columns of output; a global restart
  // record. `state_name`: prefix of the per-ball state's fix property/atom (+ the fix ID).
  FixBearingBody(class LAMMPS *, int narg, char **arg, int vector_size, int peratom_cols,
                 const char *state_name);

  // The per-ball state: created in post_create() with one default per column, found in init().
  void create_state(const std::vector<std::string> &defaults);
  void find_state();
  // The defects that act on this kind of body (fix bearing/defect, through BearingDefect).
  void find_defects(bool cage);

  // Radius and type range of the balls of the group, over all processes.
  struct GroupBalls {
    bool empty;
    double rmin, rmax;
    int tmin, tmax;
  };
  GroupBalls scan_group() const;

  // Right after read_restart: adds back the forces (columns fx, fy, and tz if >= 0) of the
  // step the restart was written at, and returns true. Recomputing them would use full-step
  // instead of half-step velocities in the damping and friction terms, and the split run
  // would drift from the single run.
  bool reapply_restored_forces(int fx, int fy, int tz);

  // Stops the run when another race or cage turns about another axis (`scale`: the length
  // below which two axes are the same, a millionth of a nanometre of the body's size).
  void check_common_axis(double scale);
  // Stops the run when another race or cage has the other model (2d, 3d).
  void check_common_model();
  // Which global outputs are sums over the balls (extensive: thermo_modify norm divides them
  // by the atom count), one flag per output.
  void set_extensive(std::vector<int> flags);
  double axis_x_ = 0, axis_y_ = 0;  // keyword centre

  class FixPropertyAtom *state_ = nullptr;  // per-ball contact state
  bool restored_ = false;                   // state was just read from a restart file
  std::vector<const ohmdem::BearingDefect *> defects_;
  ohmdem::BearingSurface defect_surface_;  // this step's surface, set only if there are defects

 private:
  std::string state_name_;
  std::vector<int> extensive_;  // LIGGGHTS' extlist points here
};

}  // namespace LAMMPS_NS

#endif
