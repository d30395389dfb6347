// SPDX-License-Identifier: GPL-2.0-or-later
// What flows between the bearing styles, as values (no style includes another): a body (a
// race or the cage) describes its surface as a BearingSurface; a defect answers queries about
// a contact on such a surface. fix bearing/race and fix bearing/cage implement BearingBody,
// fix bearing/defect implements BearingDefect; each finds the others through these
// interfaces (dynamic_cast over the fixes), so adding a body or a defect touches neither side.
#ifndef OHMDEM_BEARING_SURFACE_H
#define OHMDEM_BEARING_SURFACE_H

#include <cstdint>

namespace ohmdem {

enum class BodyKind { InnerRace, OuterRace, Cage };

struct BearingSurface {
  const void *body = nullptr;  // which body this is (compared, never dereferenced)
  BodyKind kind = BodyKind::InnerRace;
  double centre[2] = {0, 0};  // body centre (m)
  double radius = 0;          // race: radius at the groove bottom now; cage: pitch radius (m)
  double angle = 0;           // rotation of the body about z (rad)
  double ball_radius = 0;     // radius of the balls that touch it (m)
  int pockets = 0;            // cage: number of pockets
  double groove = 0;          // race: groove radius (m)
  bool three_d = false;       // race: model 3d (contacts across the groove at their angle)
  bool is_race() const { return kind != BodyKind::Cage; }
  bool inner() const { return kind == BodyKind::InnerRace; }
};

// A race pit seen from a contact (the lubricated gap's strip, doc/methods/lubricated_contact.md): the
// contact's arc offset from the pit's centre and the pit's arc width at the race's radius (m),
// its depth (m) and the radius of the ball that rolls over it (m).
struct PitView {
  double offset = 0, width = 0, depth = 0, ball_radius = 0;
};

class BearingBody {
 public:
  virtual ~BearingBody() = default;
  virtual BearingSurface surface() const = 0;
};

class BearingDefect {
 public:
  virtual ~BearingDefect() = default;
  virtual bool acts_on_races() const = 0;
  virtual bool acts_on_cage() const = 0;
  // How far the surface falls away under the contact of ball `tag` with the race `race` (m);
  // (dx, dy) is the vector from the race centre to the ball centre, on which the contact
  // lies. `masked` is set when the contact point lies in the zone (no current).
  virtual double recess(const BearingSurface &race, std::int64_t tag, double dx, double dy,
                        bool &masked) const = 0;
  // Model 3d: the same for a contact at the contact angle alpha (rad, in the race's frame), which
  // lies Rg alpha across the groove from its bottom. A defect without an extent across the
  // raceway (the whole track) answers recess().
  virtual double recess_at(const BearingSurface &race, std::int64_t tag, double dx, double dy,
                           double alpha, bool &masked) const
  {
    (void)alpha;
    return recess(race, tag, dx, dy, masked);
  }
  // The race pit on `race` whose zone comes within `reach` (m, along the race) of the contact
  // on the line (dx, dy) from the race centre, as `pit`; false when this defect has none there
  // (a ball's pit, a cage defect). Its recess at the contact is recess()'s.
  virtual bool pit_near(const BearingSurface &race, double dx, double dy, double reach,
                        PitView &pit) const
  {
    (void)race, (void)dx, (void)dy, (void)reach, (void)pit;
    return false;
  }
  // Model 3d: the same for a contact at the contact angle alpha (rad): a pit with an extent
  // across the raceway that the contact runs beside is not near it. A defect without that
  // extent answers pit_near().
  virtual bool pit_near_at(const BearingSurface &race, double dx, double dy, double alpha,
                           double reach, PitView &pit) const
  {
    (void)alpha;
    return pit_near(race, dx, dy, reach, pit);
  }
  // Whether the wall on `side` (+1 leading, -1 trailing, in the sense of increasing angle) of
  // pocket `pocket` of `cage` is broken.
  virtual bool breaks_wall(const BearingSurface &cage, int pocket, int side) const = 0;
};

}  // namespace ohmdem

#endif
