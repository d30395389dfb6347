#include "race_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ohmdem {

double restitution_beta(double restitution)
{
  if (!(restitution > 0.0 && restitution <= 1.0))
    throw std::invalid_argument("coefficient of restitution must be in (0, 1]");
  const double l = std::log(restitution);
  return l / std::sqrt(l * l + M_PI * M_PI);
}

static CurvatureSums race_curvatures(RaceSide side, double rb, double R, double Rg)
{
  if (!(rb > 0.0)) throw std::invalid_argument("ball radius must be positive");
  if (!(Rg > rb))
    throw std::invalid_argument("groove radius must be larger than the ball radius");
  if (side == RaceSide::Outer && !(R > rb))
    throw std::invalid_argument("outer race radius must be larger than the ball radius");
  return side == RaceSide::Inner ? ball_inner_race(rb, R, Rg) : ball_outer_race(rb, R, Rg);
}

RaceContactModel::RaceContactModel(RaceSide side_, double ball_radius_, double race_radius,
                                   double groove_radius, double E_eff, double G_eff_,
                                   double restitution, double friction_)
    : side(side_),
      ball_radius(ball_radius_),
      hertz(race_curvatures(side_, ball_radius_, race_radius, groove_radius), E_eff,
            AreaModel::Exact),
      G_eff(G_eff_),
      beta(restitution_beta(restitution)),
      friction(friction_)
{
  if (!(G_eff_ > 0.0)) throw std::invalid_argument("shear modulus must be positive");
  if (!(friction_ >= 0.0)) throw std::invalid_argument("friction coefficient must be >= 0");
}

RaceContactResult race_contact(const RaceContactModel &m, const RaceContactState &s, double dt,
                               bool update_history, double &shear)
{
  RaceContactResult r;
  const double dx = s.ball_x.x - s.race_centre.x;
  const double dy = s.ball_x.y - s.race_centre.y;
  const double dist = std::hypot(dx, dy);
  // A ball exactly on the race axis has no defined normal: it cannot touch a race anyway.
  if (dist <= 0.0) {
    shear = 0.0;
    return r;
  }
  r.normal = {dx / dist, dy / dist};
  const bool inner = m.side == RaceSide::Inner;
  // side: -1 when the contact is on the centre side of the ball (inner race).
  const double side = inner ? -1.0 : 1.0;
  const double delta =
      inner ? s.race_radius + m.ball_radius - dist : dist + m.ball_radius - s.race_radius;
  r.delta = delta;
  if (delta <= 0.0) {
    shear = 0.0;
    return r;
  }
  r.touching = true;

  // Lever arm from the ball centre to the contact point (middle of the overlap).
  const double arm = m.ball_radius - 0.5 * delta;
  const Vec2 lever{side * arm * r.normal.x, side * arm * r.normal.y};
  r.point = {s.ball_x.x + lever.x, s.ball_x.y + lever.y};

  // Velocities of the two material points at the contact (omega x r with omega along z).
  const Vec2 vb{s.ball_v.x - s.ball_omega * lever.y, s.ball_v.y + s.ball_omega * lever.x};
  const double px = r.point.x - s.race_centre.x;
  const double py = r.point.y - s.race_centre.y;
  // The race surface also moves radially when the ring radius changes (force control).
  const double radial = inner ? s.race_radius_rate : -s.race_radius_rate;
  const Vec2 vr{s.race_v.x - s.race_omega * py + radial * r.normal.x,
                s.race_v.y + s.race_omega * px + radial * r.normal.y};
  const Vec2 vrel{vb.x - vr.x, vb.y - vr.y};
  const Vec2 t{-r.normal.y, r.normal.x};
  const double vn = vrel.x * r.normal.x + vrel.y * r.normal.y;
  const double vt = vrel.x * t.x + vrel.y * t.y;
  const double delta_rate = side * vn;

  // Normal: exact elliptic Hertz + restitution damping (LIGGGHTS' form with S_n = dQ/ddelta).
  const double q = m.hertz.force(delta);
  const double sn = m.hertz.normal_stiffness(delta);
  const double gamma_n = -2.0 * std::sqrt(5.0 / 6.0) * m.beta * std::sqrt(sn * s.ball_mass);
  r.fn = std::max(0.0, q + gamma_n * delta_rate);

  // Tangential: Mindlin spring on the equivalent contact radius, capped by Coulomb.
  const double kt = 8.0 * m.G_eff * m.hertz.ellipse(q).c;
  const double gamma_t = -2.0 * std::sqrt(5.0 / 6.0) * m.beta * std::sqrt(kt * s.ball_mass);
  if (update_history) shear += vt * dt;
  double ft = -kt * shear - gamma_t * vt;
  const double cap = m.friction * r.fn;
  if (std::fabs(ft) > cap) {
    // Sliding: the force sits on the Coulomb cone and the spring holds what it can carry.
    ft = std::copysign(cap, ft);
    shear = kt > 0.0 ? -ft / kt : 0.0;
  }
  r.ft = ft;

  const double fnx = -side * r.fn * r.normal.x;
  const double fny = -side * r.fn * r.normal.y;
  r.force_on_ball = {fnx + ft * t.x, fny + ft * t.y};
  r.torque_on_ball = lever.x * (ft * t.y) - lever.y * (ft * t.x);
  r.torque_on_race = -(px * r.force_on_ball.y - py * r.force_on_ball.x);
  return r;
}

}  // namespace ohmdem
