#include "cage_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ohmdem {

CageContactModel::CageContactModel(double ball_radius_, double clearance_, double E_eff,
                                   double restitution)
    : ball_radius(ball_radius_),
      clearance(clearance_),
      hertz(sphere_flat(ball_radius_), E_eff, AreaModel::Exact),
      beta(restitution_beta(restitution))
{
  if (!(clearance_ >= 0.0)) throw std::invalid_argument("pocket clearance must be >= 0");
}

CageContactResult cage_contact(const CageContactModel &m, const CageContactState &s)
{
  CageContactResult r;
  const Vec2 t{-std::sin(s.pocket_angle), std::cos(s.pocket_angle)};  // pocket tangent
  const double dx = s.ball_x.x - s.centre.x;
  const double dy = s.ball_x.y - s.centre.y;
  r.offset = dx * t.x + dy * t.y;
  const double delta = std::fabs(r.offset) - m.clearance;
  r.delta = delta;
  if (delta <= 0.0) return r;
  r.touching = true;
  const double side = r.offset > 0.0 ? 1.0 : -1.0;  // which wall: +t or -t side

  // Contact point on the ball, facing the wall, and the wall's velocity there.
  const double arm = m.ball_radius - 0.5 * delta;
  const Vec2 p{s.ball_x.x + side * arm * t.x, s.ball_x.y + side * arm * t.y};
  const double px = p.x - s.centre.x, py = p.y - s.centre.y;
  const Vec2 vw{-s.cage_omega * py, s.cage_omega * px};
  // Ball spin does not move the contact point along the wall normal: only v matters.
  const double delta_rate = side * ((s.ball_v.x - vw.x) * t.x + (s.ball_v.y - vw.y) * t.y);

  const double q = m.hertz.force(delta);
  const double sn = m.hertz.normal_stiffness(delta);
  const double gamma_n = -2.0 * std::sqrt(5.0 / 6.0) * m.beta * std::sqrt(sn * s.ball_mass);
  r.fn = std::max(0.0, q + gamma_n * delta_rate);
  r.force_on_ball = {-side * r.fn * t.x, -side * r.fn * t.y};
  r.torque_on_cage = -(px * r.force_on_ball.y - py * r.force_on_ball.x);
  return r;
}

}  // namespace ohmdem
