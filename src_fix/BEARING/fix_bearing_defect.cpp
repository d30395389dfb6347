// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix bearing/defect. Pit geometry in contact/defect_geometry.*; the
   races and the cage ask this fix about each contact (recess(), breaks_wall()),
   passing their surface as a value (support/bearing_surface.h).
------------------------------------------------------------------------- */

#include "BEARING/fix_bearing_defect.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "atom.h"
#include "comm.h"
#include "common/constants.h"
#include "contact/defect_geometry.h"
#include "error.h"
#include "group.h"
#include "modify.h"
#include "support/args.h"
#include "support/require_si.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr double kDeg = ohmdem::kDegree;

// A number as a user would write it (6 significant digits, no trailing zeros).
std::string number_text(double v)
{
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}
}  // namespace

FixBearingDefect::FixBearingDefect(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  ohmdem::StyleArgs a(error, "fix bearing/defect", narg, arg, 3);
  const std::string kind = a.word("kind", "none, inner, outer, ball or cage as first argument");
  if (kind == "none")
    kind_ = Kind::None;
  else if (kind == "inner")
    kind_ = Kind::Inner;
  else if (kind == "outer")
    kind_ = Kind::Outer;
  else if (kind == "ball")
    kind_ = Kind::Ball;
  else if (kind == "cage")
    kind_ = Kind::Cage;
  else
    a.fail("kind", "none, inner, outer, ball or cage as first argument", kind.c_str());
  // Keywords that the kind does not use are read and ignored, so that one deck line with
  // -var defect KIND serves every kind.
  bool have_size = false, have_pocket = false;
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "race") {
      races_.push_back(a.word(kw, "the ID of a fix bearing/race"));
    } else if (kw == "atom") {
      ball_ = a.integer(kw, "the atom ID of the defective ball", 1, 2147483647);
    } else if (kw == "cage") {
      target_ = a.word(kw, "the ID of a fix bearing/cage");
    } else if (kw == "position") {
      position_ = a.number(kw, "the angular position of the zone centre (degrees)") * kDeg;
    } else if (kw == "size") {
      size_ = a.positive(kw, "the angular size of the zone, > 0 (degrees)") * kDeg;
      arc_ = 0.0;
      have_size = true;
    } else if (kw == "arc") {
      arc_ = a.positive(kw, "the size of the zone as an arc length on the surface, > 0 (m)");
      size_ = 0.0;
      have_size = true;
    } else if (kw == "start") {
      start_ = a.non_negative(kw, "the time from which the defect exists, >= 0 (s)");
    } else if (kw == "depth") {
      depth_ = a.positive(kw, "the pit depth, > 0 (m)");
    } else if (kw == "pocket") {
      pocket_ = a.integer(kw, "a pocket index 0..N-1", 0, 1 << 30);
      have_pocket = true;
    } else if (kw == "side") {
      const std::string sd = a.word(kw, "leading or trailing");
      if (sd == "leading")
        side_ = 1;
      else if (sd == "trailing")
        side_ = -1;
      else
        a.fail(kw, "leading or trailing", sd.c_str());
    } else if (kw == "width") {
      width_ =
          a.non_negative(kw, "the pit's extent across the raceway, >= 0 (m; 0: the whole track)");
    } else if (kw == "track") {
      track_ = a.number(kw, "the contact angle of the pit's centre line (degrees)") * kDeg;
    } else {
      a.unknown(kw.c_str(), "race atom cage position size arc depth start pocket side width track");
    }
  }
  const bool zone = kind_ == Kind::Inner || kind_ == Kind::Outer || kind_ == Kind::Ball;
  if (zone && !have_size)
    a.fail("size", "a value: 'size DEGREES' or 'arc LENGTH' is required", "nothing");
  // A zone that covers its whole surface is no defect: a race zone below one turn, a ball zone
  // below half a turn (the ball's contacts with the two races are half a turn apart).
  const std::string got = number_text(size_ / kDeg);
  if ((kind_ == Kind::Inner || kind_ == Kind::Outer) && size_ >= 2.0 * ohmdem::kPi)
    a.fail("size", "the angular size of a race zone, in (0, 360) degrees", got.c_str());
  if (kind_ == Kind::Ball && size_ >= ohmdem::kPi)
    a.fail("size", "the angular size of a ball zone, in (0, 180) degrees", got.c_str());
  if ((kind_ == Kind::Inner || kind_ == Kind::Outer) && races_.empty())
    a.fail("race", "the ID of the defective fix bearing/race: the keyword is required", "nothing");
  if (kind_ == Kind::Ball && ball_ == 0)
    a.fail("atom", "the atom ID of the defective ball: the keyword is required", "nothing");
  if (kind_ == Kind::Cage && (target_.empty() || !have_pocket))
    a.fail(target_.empty() ? "cage" : "pocket",
           "a value: a cage defect needs 'cage ID' and 'pocket K'", "nothing");

  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

int FixBearingDefect::setmask()
{
  return kind_ == Kind::Ball ? POST_INTEGRATE : 0;
}

// The fix `id` if it is a race (cage = false) or a cage (cage = true), else null.
const ohmdem::BearingBody *FixBearingDefect::find_body(const std::string &id, bool cage) const
{
  const int k = modify->find_fix(id.c_str());
  const auto *body = k >= 0 ? dynamic_cast<const ohmdem::BearingBody *>(modify->fix[k]) : nullptr;
  if (!body || body->surface().is_race() == cage) return nullptr;
  return body;
}

void FixBearingDefect::init()
{
  ohmdem::require_si_units(lmp, "fix bearing/defect");
  race_ = nullptr;
  cage_ = nullptr;
  auto fail = [&](const std::string &msg) {
    error->all(FLERR, ("fix bearing/defect: " + msg).c_str());
  };
  if (kind_ == Kind::Inner || kind_ == Kind::Outer) {
    const bool want_inner = kind_ == Kind::Inner;
    for (const auto &name : races_) {
      const ohmdem::BearingBody *race = find_body(name, false);
      if (!race) fail("keyword 'race' expects the ID of a fix bearing/race, got '" + name + "'");
      if (race->surface().inner() == want_inner) race_ = race;
    }
    if (!race_)
      fail(std::string("an ") + (want_inner ? "inner" : "outer") + " defect needs an " +
           (want_inner ? "inner" : "outer") + " race among the 'race' IDs");
    if (width_ > 0.0 && !race_->surface().three_d)
      fail(
          "keyword 'width' expects 0 with a model 2d race (its contacts have no place across "
          "the groove), got " +
          number_text(width_));
  } else if (kind_ == Kind::Ball) {
    // On a model 3d bearing the ball turns in space: its orientation carries the pit.
    three_d_ = false;
    for (int k = 0; k < modify->nfix; ++k) {
      const auto *body = dynamic_cast<const ohmdem::BearingBody *>(modify->fix[k]);
      if (body && body->surface().is_race() && body->surface().three_d) three_d_ = true;
    }
  } else if (kind_ == Kind::Cage) {
    cage_ = find_body(target_, true);
    if (!cage_) fail("keyword 'cage' expects the ID of a fix bearing/cage, got '" + target_ + "'");
    const int pockets = cage_->surface().pockets;
    if (pocket_ >= pockets)
      fail("keyword 'pocket' expects a pocket index 0.." + std::to_string(pockets - 1) + ", got " +
           std::to_string(pocket_));
  }
}

void FixBearingDefect::setup(int)
{
  if (kind_ == Kind::Inner || kind_ == Kind::Outer) {
    // An arc longer than the race is no zone (the ball would never leave it): refused as an
    // angular size of 360 degrees or more is.
    const double circumference = 2.0 * ohmdem::kPi * race_->surface().radius;
    if (arc_ > 0.0 && arc_ >= circumference) {
      const std::string msg =
          "fix bearing/defect: keyword 'arc' expects the arc length of a race zone, in (0, " +
          number_text(circumference) + ") m (the circumference of this race, radius " +
          number_text(race_->surface().radius) + " m), got " + number_text(arc_);
      error->all(FLERR, msg.c_str());
    }
    // Legal but odd: a race zone wider than the ball spacing holds two balls at times.
    const bigint balls = group->count(igroup);
    const double spacing = balls > 0 ? 2.0 * ohmdem::kPi / static_cast<double>(balls) : 0.0;
    if (balls > 0 && size_ > spacing && comm->me == 0 && !warned_wide_) {
      const std::string msg = "fix bearing/defect: the zone (" + number_text(size_ / kDeg) +
                              " deg) is wider than the ball spacing (360/" + std::to_string(balls) +
                              " = " + number_text(spacing / kDeg) +
                              " deg): two balls can be in it at once";
      error->warning(FLERR, msg.c_str());
    }
    warned_wide_ = true;
    return;
  }
  if (kind_ != Kind::Ball) return;
  // The defective ball must exist; its radius sets the size of an angular zone. (map() does
  // not check its argument: stay within the IDs it knows.)
  const int i = ball_ <= atom->map_tag_max ? atom->map(ball_) : -1;
  double mine[2] = {0.0, 0.0};
  if (i >= 0 && i < atom->nlocal) {
    mine[0] = 1.0;
    mine[1] = atom->radius[i];
  }
  double all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  if (all[0] != 1.0) {
    const std::string msg =
        "fix bearing/defect: keyword 'atom' expects the atom ID of a ball, "
        "got " +
        std::to_string(ball_) + " (no such atom)";
    error->all(FLERR, msg.c_str());
  }
  ball_radius_ = all[1];
  if (arc_ > 0.0 && arc_ >= ohmdem::kPi * ball_radius_) {
    const std::string msg =
        "fix bearing/defect: keyword 'arc' expects the arc length of a ball zone, in (0, " +
        number_text(ohmdem::kPi * ball_radius_) + ") m (half the ball's circumference), got " +
        number_text(arc_);
    error->all(FLERR, msg.c_str());
  }
}

// The ball's surface turns with it: integrate its spin about z (model 2d), and in model 3d its
// orientation in space as well.
void FixBearingDefect::post_integrate()
{
  const int i = ball_ <= atom->map_tag_max ? atom->map(ball_) : -1;
  const bool mine = i >= 0 && i < atom->nlocal;
  if (three_d_) {
    double w[3] = {0.0, 0.0, 0.0}, all[3];
    if (mine)
      for (int k = 0; k < 3; ++k) w[k] = atom->omega[i][k];
    MPI_Allreduce(w, all, 3, MPI_DOUBLE, MPI_SUM, world);
    orientation_.turn({all[0], all[1], all[2]}, update->dt);
    spin_ += all[2] * update->dt;
    return;
  }
  double w = mine ? atom->omega[i][2] : 0.0;
  if (comm->nprocs > 1) {
    double sum = 0.0;
    MPI_Allreduce(&w, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
    w = sum;
  }
  spin_ += w * update->dt;
}

double FixBearingDefect::zone_centre() const
{
  if (kind_ == Kind::Ball && three_d_) {
    const ohmdem::Vec3 c = orientation_.apply(ohmdem::ball_pit_centre(position_, track_));
    return std::atan2(c.y, c.x);  // the azimuth of the pit's centre
  }
  switch (kind_) {
    case Kind::Inner:
    case Kind::Outer:
      return zone_centre(race_ ? race_->surface().angle : 0.0);
    case Kind::Cage:
      return zone_centre(cage_ ? cage_->surface().angle : 0.0);
    default:
      return zone_centre(0.0);
  }
}

double FixBearingDefect::zone_centre(double body_angle) const
{
  switch (kind_) {
    case Kind::Inner:
    case Kind::Outer:
      return position_ + body_angle;
    case Kind::Ball:
      return position_ + spin_;
    case Kind::Cage:
      return body_angle;
    case Kind::None:
      return 0.0;
  }
  return 0.0;
}

bool FixBearingDefect::active() const
{
  return update->ntimestep * update->dt >= start_;  // the deck's clock: step*dt
}

double FixBearingDefect::recess(const ohmdem::BearingSurface &race, std::int64_t tag, double dx,
                                double dy, bool &masked) const
{
  if (!active()) return 0.0;
  double s = 0.0;
  ohmdem::Pit pit;
  pit.depth = depth_;
  if ((kind_ == Kind::Inner || kind_ == Kind::Outer) && race.body == race_) {
    const double R = race.radius;
    s = R * ohmdem::wrap_angle(std::atan2(dy, dx) - zone_centre(race.angle));
    pit.width = arc_ > 0.0 ? arc_ : R * size_;
    pit.ball_radius = race.ball_radius;
  } else if (kind_ == Kind::Ball && tag == ball_) {
    // Direction from the ball centre to the contact: toward the axis on an inner race.
    const double direction = race.inner() ? std::atan2(-dy, -dx) : std::atan2(dy, dx);
    s = ball_radius_ * ohmdem::wrap_angle(direction - zone_centre(0.0));
    pit.width = arc_ > 0.0 ? arc_ : ball_radius_ * size_;
    pit.ball_radius = ball_radius_;
  } else {
    return 0.0;
  }
  if (ohmdem::in_pit(pit, s)) masked = true;
  return ohmdem::pit_recess(pit, s);
}

// Model 3d: a pit `width` across the raceway, centred on the contact angle `track`, holds the
// contacts whose centre lies Rg (alpha - track) across the groove within it; the recess is the
// smaller of the profiles along and across (the ball rests on the nearer edge).
double FixBearingDefect::recess_at(const ohmdem::BearingSurface &race, std::int64_t tag, double dx,
                                   double dy, double alpha, bool &masked) const
{
  if (kind_ == Kind::Ball && three_d_)
    return tag == ball_ && active() ? ball_recess_3d(race, dx, dy, alpha, masked) : 0.0;
  if (!(width_ > 0.0) || !(kind_ == Kind::Inner || kind_ == Kind::Outer))
    return recess(race, tag, dx, dy, masked);
  if (race.body != race_) return 0.0;
  ohmdem::Pit across;
  across.width = width_;
  across.depth = depth_;
  across.ball_radius = race.ball_radius;
  const double s = race.groove * (alpha - track_);
  if (!ohmdem::in_pit(across, s)) return 0.0;  // beside the pit: not felt, not masked
  return std::min(recess(race, tag, dx, dy, masked), ohmdem::pit_recess(across, s));
}

// Model 3d, the defective ball's contact on `race` at contact angle alpha: its great-circle
// distance on the ball from the pit's centre, carried by the ball's orientation. The contact's
// direction is taken in the bearing plane and alpha (a tilted ring's mrad left out).
double FixBearingDefect::ball_recess_3d(const ohmdem::BearingSurface &race, double dx, double dy,
                                        double alpha, bool &masked) const
{
  const double rho = std::hypot(dx, dy);
  if (!(rho > 0.0)) return 0.0;
  const ohmdem::Vec3 n = ohmdem::contact_direction({dx / rho, dy / rho, 0.0}, alpha, race.inner());
  const ohmdem::Vec3 c = orientation_.apply(ohmdem::ball_pit_centre(position_, track_));
  ohmdem::Pit pit;
  pit.depth = depth_;
  pit.width = arc_ > 0.0 ? arc_ : ball_radius_ * size_;
  pit.ball_radius = ball_radius_;
  const double s = ball_radius_ * ohmdem::angle_between(n, c);
  if (ohmdem::in_pit(pit, s)) masked = true;
  return ohmdem::pit_recess(pit, s);
}

// The same arc offset and width as recess(), for the lubricated gap (a query: the mechanics do
// not call it).
bool FixBearingDefect::pit_near(const ohmdem::BearingSurface &race, double dx, double dy,
                                double reach, ohmdem::PitView &pit) const
{
  if (!(kind_ == Kind::Inner || kind_ == Kind::Outer) || race.body != race_ || !active())
    return false;
  const double R = race.radius;
  const double s = R * ohmdem::wrap_angle(std::atan2(dy, dx) - zone_centre(race.angle));
  const double width = arc_ > 0.0 ? arc_ : R * size_;
  if (!(std::fabs(s) - 0.5 * width < reach)) return false;
  pit.offset = s;
  pit.width = width;
  pit.depth = depth_;
  pit.ball_radius = race.ball_radius;
  return true;
}

// Model 3d: beside a pit narrower than the track (recess_at's test across the groove) the
// contact's film does not meet it.
bool FixBearingDefect::pit_near_at(const ohmdem::BearingSurface &race, double dx, double dy,
                                   double alpha, double reach, ohmdem::PitView &pit) const
{
  if (width_ > 0.0 && (kind_ == Kind::Inner || kind_ == Kind::Outer)) {
    ohmdem::Pit across;
    across.width = width_;
    across.depth = depth_;
    across.ball_radius = race.ball_radius;
    if (!ohmdem::in_pit(across, race.groove * (alpha - track_))) return false;
  }
  return pit_near(race, dx, dy, reach, pit);
}

// The broken bar separates pocket K from its neighbour on `side`: it is the wall on that side
// of pocket K and the opposite wall of the neighbour.
bool FixBearingDefect::breaks_wall(const ohmdem::BearingSurface &cage, int pocket, int side) const
{
  if (kind_ != Kind::Cage || cage.body != cage_ || !active()) return false;
  const int n = cage.pockets;
  const int neighbour = ((pocket_ + side_) % n + n) % n;
  return (pocket == pocket_ && side == side_) || (pocket == neighbour && side == -side_);
}

double FixBearingDefect::compute_vector(int n)
{
  if (n == 0) {
    const double deg = std::fmod(zone_centre() / kDeg, 360.0);
    return deg < 0.0 ? deg + 360.0 : deg;
  }
  return n == 1 ? spin_ / kDeg : 0.0;
}

// The record: the spin and the kind, and for a ball of a model 3d bearing its orientation
// (the kind's code then plus kOriented, so that a planar record keeps its two values).
namespace {
constexpr int kOriented = 16;
}

void FixBearingDefect::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const bool oriented = kind_ == Kind::Ball && three_d_;
  const double code = static_cast<int>(kind_) + (oriented ? kOriented : 0);
  const double list[6] = {spin_,          code,           orientation_.w,
                          orientation_.x, orientation_.y, orientation_.z};
  const int n = oriented ? 6 : 2;
  const int size = n * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), n, fp);
}

void FixBearingDefect::restart(char *buf)
{
  const double *list = reinterpret_cast<const double *>(buf);
  int code = static_cast<int>(list[1]);
  const bool oriented = code >= kOriented;
  if (oriented) code -= kOriented;
  if (code != static_cast<int>(kind_))
    error->fix_error(FLERR, this, "restart data is for another kind of defect");
  spin_ = list[0];
  if (oriented) {
    orientation_.w = list[2];
    orientation_.x = list[3];
    orientation_.y = list[4];
    orientation_.z = list[5];
  }
}
