/* ----------------------------------------------------------------------
   ohmdem - fix bearing/defect: a local defect of a bearing (a pit on a race
   or on a ball, or a broken cage bar), seen by fix bearing/race and fix
   bearing/cage as a contact break.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(bearing/defect,FixBearingDefect)

#else

#ifndef LMP_FIX_BEARING_DEFECT_H
#define LMP_FIX_BEARING_DEFECT_H

#include <string>
#include <vector>

#include "fix.h"

namespace LAMMPS_NS {

class FixBearingRace;
class FixBearingCage;

class FixBearingDefect : public Fix {
 public:
  enum class Kind { None, Inner, Outer, Ball, Cage };

  FixBearingDefect(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_integrate() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double compute_vector(int) override;

  Kind kind() const { return kind_; }
  // For fix bearing/race: how far the surface falls away under the contact of ball `tag`
  // with `race` (m); (dx, dy) is the vector from the race centre to the ball centre, on which
  // the contact lies. `masked` is set when the contact point lies in the zone (no current).
  double recess(const FixBearingRace *race, tagint tag, double dx, double dy,
                bool &masked) const;
  // For fix bearing/cage: whether the wall on `side` (+1 leading, -1 trailing, in the sense
  // of increasing angle) of pocket k is broken.
  bool breaks_wall(const FixBearingCage *cage, int pocket, int side) const;

 private:
  double zone_centre() const;  // lab angle of the zone centre (rad)
  bool active() const;         // the defect exists from time `start` on

  Kind kind_ = Kind::Inner;
  std::vector<std::string> races_;  // inner/outer: candidate race IDs
  std::string target_;              // cage ID
  FixBearingRace *race_ = nullptr;
  FixBearingCage *cage_ = nullptr;
  tagint ball_ = 0;           // ball defect: the ball's atom ID
  double position_ = 0;       // zone centre in the body frame (rad)
  double size_ = 0;           // angular size (rad); 0 when given as an arc length
  double arc_ = 0;            // arc length (m); 0 when given as an angle
  double depth_ = 5e-6;       // pit depth (m)
  double start_ = 0;          // time from which the defect exists (s)
  int pocket_ = 0, side_ = 1;  // cage defect
  double spin_ = 0;           // ball defect: the ball's rotation angle about z (rad)
  double ball_radius_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
