// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/defect: a local defect of a bearing (a pit on a race
   or on a ball, or a broken cage bar), seen by fix bearing/race and fix
   bearing/cage as a contact break.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(bearing/defect,FixBearingDefect)
// clang-format on

#else

#ifndef LMP_FIX_BEARING_DEFECT_H
#define LMP_FIX_BEARING_DEFECT_H

#include <string>
#include <vector>

#include "contact/ball_pit_3d.h"
#include "fix.h"
#include "support/bearing_surface.h"

namespace LAMMPS_NS {

// Knows the races and the cage only as BearingBody (support/bearing_surface.h): it reads
// their surface as a value and answers their queries; it includes neither of their headers.
class FixBearingDefect : public Fix, public ohmdem::BearingDefect {
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
  bool acts_on_races() const override
  {
    return kind_ == Kind::Inner || kind_ == Kind::Outer || kind_ == Kind::Ball;
  }
  bool acts_on_cage() const override { return kind_ == Kind::Cage; }
  double recess(const ohmdem::BearingSurface &race, std::int64_t tag, double dx, double dy,
                bool &masked) const override;
  double recess_at(const ohmdem::BearingSurface &race, std::int64_t tag, double dx, double dy,
                   double alpha, bool &masked) const override;
  bool pit_near(const ohmdem::BearingSurface &race, double dx, double dy, double reach,
                ohmdem::PitView &pit) const override;
  bool pit_near_at(const ohmdem::BearingSurface &race, double dx, double dy, double alpha,
                   double reach, ohmdem::PitView &pit) const override;
  bool breaks_wall(const ohmdem::BearingSurface &cage, int pocket, int side) const override;

 private:
  double zone_centre() const;                   // lab angle of the zone centre (rad)
  double zone_centre(double body_angle) const;  // the same, given the defective body's angle
  const ohmdem::BearingBody *find_body(const std::string &id, bool cage) const;
  bool active() const;  // the defect exists from time `start` on

  Kind kind_ = Kind::Inner;
  std::vector<std::string> races_;             // inner/outer: candidate race IDs
  std::string target_;                         // cage ID
  const ohmdem::BearingBody *race_ = nullptr;  // inner/outer: the defective race
  const ohmdem::BearingBody *cage_ = nullptr;  // cage: the defective cage
  tagint ball_ = 0;                            // ball defect: the ball's atom ID
  double position_ = 0;                        // zone centre in the body frame (rad)
  double size_ = 0;                            // angular size (rad); 0 when given as an arc length
  double arc_ = 0;                             // arc length (m); 0 when given as an angle
  double depth_ = 5e-6;                        // pit depth (m)
  double start_ = 0;                           // time from which the defect exists (s)
  int pocket_ = 0, side_ = 1;                  // cage defect
  double spin_ = 0;  // ball defect: the ball's rotation angle about z (rad)
  // Ball defect on a model 3d bearing: the ball's orientation in space, and the pit's centre in
  // its body frame (position and track: azimuth and latitude at the start).
  bool three_d_ = false;
  ohmdem::BallOrientation orientation_;
  double ball_recess_3d(const ohmdem::BearingSurface &race, double dx, double dy, double alpha,
                        bool &masked) const;
  double width_ = 0;  // race pit, model 3d: its extent across the raceway (m); 0: the whole track
  double track_ = 0;  // the contact angle of its centre line (rad); a ball pit: its latitude
  double ball_radius_ = 0;
  bool warned_wide_ = false;  // the wide-zone warning, once per fix
};

}  // namespace LAMMPS_NS

#endif
#endif
