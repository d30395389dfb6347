// SPDX-License-Identifier: GPL-2.0-or-later
// The gap and the Hertz zone over a pit strip (src_fix/lib/lubrication/pit_gap.*), against
// gap_capacitance's closed form (no strip; a strip over the whole circle is h0 + depth), a
// brute-force 2D quadrature written here (polar coordinates, 1/h summed directly: neither the
// kernel's arctangent nor its x-pieces), and the Hertz zone's closed forms for a flat floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "lubrication/contact_admittance.h"
#include "lubrication/pit_gap.h"
#include "test_constants.h"

using namespace ohmdem::lubrication;
using ohmdem::test::kPi;

namespace {

// A 6208 inner contact (Hamrock's Rx = d (dm - d) / (2 dm), Ry = f d / (2f - 1) for
// d = 12.6 mm, dm = 60 mm, f = 0.52), a Hertz ellipse of k ~ 9 at ~15 N, the deck's wetted
// radius 0.1 Db.
GapGeometry inner_contact(double h0 = 1e-6)
{
  return GapGeometry{h0, 4.977e-3, 0.1638, 0.30e-3, 0.032e-3, 1.26e-3};
}
constexpr double kEps = 2.07;
constexpr double kBall = 6.3e-3;  // the 6208's ball radius: the profile's sag

// The profile, written here again (pit_recess of contact/defect_geometry.h): min(depth, sag)
// with the sag R - sqrt(R^2 - d^2) at the distance d to the nearer edge; R = 0: flat.
double profile(const PitStrip &p, double x)
{
  if (x <= p.x1 || x >= p.x2) return 0.0;
  if (p.edge_radius == 0.0) return p.depth;
  const double d = std::fmin(x - p.x1, p.x2 - x), r = p.edge_radius;
  return std::fmin(p.depth, d < r ? r - std::sqrt(r * r - d * d) : r);
}

// eps0 eps_r int dA / h over the circle minus the ellipse, in polar coordinates: the angle by
// the midpoint rule (n_theta), the radius split where it crosses the lines x = const at which
// the profile is not smooth, each piece by `panels` panels of 16-point Gauss-Legendre (nodes
// from the Golub-Welsch-free Newton iteration below).
struct Gauss16 {
  double x[16], w[16];
  Gauss16()
  {
    for (int i = 0; i < 16; ++i) {
      double z = std::cos(kPi * (i + 0.75) / 16.5), dp = 0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = 0;
        for (int j = 1; j <= 16; ++j) {
          const double p2 = p1;
          p1 = p0;
          p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
        }
        dp = 16 * (z * p0 - p1) / (z * z - 1.0);
        const double z1 = z;
        z = z1 - p0 / dp;
        if (std::fabs(z - z1) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};

double brute_force(const GapGeometry &g, const PitStrip &p, int n_theta, int panels)
{
  static const Gauss16 gl;
  std::vector<double> lines = {p.x1, p.x2, 0.5 * (p.x1 + p.x2)};
  if (p.edge_radius > 0.0) {
    const double d = std::sqrt(p.depth * (2.0 * p.edge_radius - p.depth));
    lines.push_back(p.x1 + d);
    lines.push_back(p.x2 - d);
  }
  long double sum = 0.0L;
  for (int k = 0; k < n_theta; ++k) {
    const double th = 2.0 * kPi * (k + 0.5) / n_theta, c = std::cos(th), s = std::sin(th);
    const double r_in =
        g.a > 0.0 ? 1.0 / std::sqrt(c * c / (g.b * g.b) + s * s / (g.a * g.a)) : 0.0;
    if (r_in >= g.r_wet) continue;
    std::vector<double> rs = {r_in, g.r_wet};
    for (const double xl : lines) {
      const double r = std::fabs(c) > 1e-300 ? xl / c : -1.0;
      if (r > r_in && r < g.r_wet) rs.push_back(r);
    }
    std::sort(rs.begin(), rs.end());
    for (std::size_t j = 0; j + 1 < rs.size(); ++j)
      for (int q = 0; q < panels; ++q) {
        const double u = rs[j] + (rs[j + 1] - rs[j]) * q / panels;
        const double v = rs[j] + (rs[j + 1] - rs[j]) * (q + 1) / panels;
        for (int i = 0; i < 16; ++i) {
          const double r = 0.5 * (u + v) + 0.5 * (v - u) * gl.x[i];
          const double x = r * c, y = r * s;
          const double h = g.h0 + x * x / (2.0 * g.rx) + y * y / (2.0 * g.ry) + profile(p, x);
          sum += 0.5 * (v - u) * gl.w[i] * r / h;
        }
      }
  }
  return kEpsilon0 * kEps * static_cast<double>(sum) * 2.0 * kPi / n_theta;
}

}  // namespace

TEST(PitGap, StripOutsideTheCircleOrWithoutDepthChangesNothing)
{
  const GapGeometry g = inner_contact();
  const double base = gap_capacitance(g, kEps);
  EXPECT_EQ(strip_gap_capacitance(g, kEps, PitStrip{1.3e-3, 1.7e-3, 5e-6, kBall}), base);
  EXPECT_EQ(strip_gap_capacitance(g, kEps, PitStrip{-2e-3, -1.26e-3, 5e-6, 0.0}), base);
  EXPECT_EQ(strip_gap_capacitance(g, kEps, PitStrip{-0.2e-3, 0.2e-3, 0.0, kBall}), base);
}

TEST(PitGap, StripOverTheWholeCircleIsTheGapPlusTheDepth)
{
  // Flat, and rounded by the ball but reaching the floor everywhere inside the circle (the
  // edges 5 mm away, sag there > 5 um): both are the closed form at h0 + depth.
  for (const GapGeometry &g :
       {inner_contact(), inner_contact(1e-7), GapGeometry{2e-6, 3e-3, 3e-3, 0.0, 0.0, 1.26e-3}}) {
    for (const double depth : {0.24e-6, 5e-6, 1e-4}) {
      GapGeometry deep = g;
      deep.h0 += depth;
      const double want = gap_capacitance(deep, kEps);
      for (const double r : {0.0, kBall})
        EXPECT_NEAR(strip_gap_capacitance(g, kEps, PitStrip{-5e-3, 5e-3, depth, r}) / want, 1.0,
                    1e-10)
            << "h0 " << g.h0 << " depth " << depth << " edge radius " << r;
    }
  }
}

TEST(PitGap, BruteForceAgreesWithoutAStrip)
{
  // The reference itself, against the closed form: its own error (measured 2e-12 relative
  // without a strip; the strip's corners make it second order in the angle step, below).
  const GapGeometry g = inner_contact();
  const double bf = brute_force(g, PitStrip{1.0, 2.0, 0.0, 0.0}, 4000, 4);
  EXPECT_NEAR(bf / gap_capacitance(g, kEps), 1.0, 1e-8);
}

TEST(PitGap, NarrowWideAndStraddlingStripsAgainstBruteForce)
{
  // The inner 1 deg pit (0.42 mm at the 6208's inner groove radius) in several places, a wide
  // flat strip, and strips straddling the ellipse's end and the circle's edge. Tolerance on the
  // capacitance's change: 3e-7 of it. The kernel's error is 1e-11 of the total by its
  // tolerance; the brute force's on the change is second order in the angle step (the strip's
  // corners): with 4000 angles it was off by up to 1.7e-6, with 16000 by 1.1e-7, each time
  // toward the kernel's value.
  const GapGeometry g = inner_contact();
  const double base = gap_capacitance(g, kEps);
  const int n_theta = 16000;
  const double bf0 = brute_force(g, PitStrip{1.0, 2.0, 0.0, 0.0}, n_theta, 4);
  const double w = 0.42e-3;
  struct Case {
    double x1, x2, depth, r;
  };
  for (const Case &c : {Case{-w / 2, w / 2, 5e-6, kBall},         // pit under the contact
                        Case{-w / 2, w / 2, 5e-6, 0.0},           // the same, flat floor
                        Case{0.5e-3, 0.5e-3 + w, 5e-6, kBall},    // ahead, inside the circle
                        Case{1.1e-3, 1.1e-3 + w, 5e-6, 0.0},      // across the circle's edge
                        Case{0.01e-3, 0.01e-3 + w, 5e-6, kBall},  // across the ellipse's end
                        Case{-0.7e-3, 2e-3, 20e-6, 0.0},          // wide, flat
                        Case{-0.1e-3, 0.05e-3, 5e-6, kBall}}) {   // narrower than the sag
    const PitStrip p{c.x1, c.x2, c.depth, c.r};
    const double kernel = strip_gap_capacitance(g, kEps, p) - base;
    const double brute = brute_force(g, p, n_theta, 4) - bf0;
    EXPECT_LT(kernel, 0.0);
    EXPECT_NEAR(kernel / brute, 1.0, 3e-7) << "strip " << c.x1 << " .. " << c.x2;
  }
}

TEST(PitGap, StiffThinFilmsAndHugeDepthsStayFinite)
{
  for (const double h0 : {1e-12, 1e-9, 1e-6})
    for (const double depth : {1e-9, 5e-6, 1.0, 1e6}) {
      const GapGeometry g = inner_contact(h0);
      const double base = gap_capacitance(g, kEps);
      for (const double x1 : {-1.5e-3, -0.1e-3, 0.0}) {
        const double c = strip_gap_capacitance(g, kEps, PitStrip{x1, x1 + 0.42e-3, depth, kBall});
        EXPECT_TRUE(std::isfinite(c) && c > 0.0 && c <= base) << h0 << " " << depth << " " << x1;
        const double flat =
            strip_gap_capacitance(g, kEps, PitStrip{-2e-3, x1 + 0.42e-3, depth, 0.0});
        EXPECT_TRUE(std::isfinite(flat) && flat > 0.0 && flat <= base) << h0 << " " << depth;
      }
    }
  // Without an ellipse (nothing excluded) and a thin film, the peak at the centre is sharp
  // (width sqrt(2 rx h0) = 0.3 um): against the closed form at h0 + depth when the strip
  // covers the circle.
  const GapGeometry bare{1e-11, 4.977e-3, 0.1638, 0.0, 0.0, 1.26e-3};
  GapGeometry deep = bare;
  deep.h0 += 5e-6;
  EXPECT_NEAR(strip_gap_capacitance(bare, kEps, PitStrip{-2e-3, 2e-3, 5e-6, 0.0}) /
                  gap_capacitance(deep, kEps),
              1.0, 1e-9);
}

TEST(PitGap, BadStripsAreRefused)
{
  const GapGeometry g = inner_contact();
  EXPECT_THROW(strip_gap_capacitance(g, kEps, PitStrip{1e-4, 1e-4, 5e-6, 0.0}),
               std::invalid_argument);
  EXPECT_THROW(strip_gap_capacitance(g, kEps, PitStrip{0.0, 1e-4, -1e-6, 0.0}),
               std::invalid_argument);
  EXPECT_THROW(strip_gap_capacitance(g, kEps, PitStrip{0.0, 1e-4, std::nan(""), 0.0}),
               std::invalid_argument);
  EXPECT_THROW(
      hertz_over_pit(HertzFilm{1e-6, 1e-6, 1e-7, 3e-4, 3e-5}, PitStrip{0.0, 1e-4, 1e-6, -1.0}),
      std::invalid_argument);
}

// The Hertz zone, flat floor of depth D over x in (x1, x2) inside the ellipse: the strip's
// area is a b [t + sin t cos t] between t = asin(x/b), and each part has its own gap.
TEST(PitGap, HertzZoneOverAFlatFloorIsTheAreaWeightedSum)
{
  const HertzFilm film{1.1e-6, 0.95e-6, 0.3e-6, 0.30e-3, 0.032e-3};
  const double area = kPi * film.a * film.b, k = 1.0 / (film.sigma * std::sqrt(2.0));
  const double f0 = std::erfc(film.h_min * k);
  for (const double depth : {0.2e-6, 5e-6})
    for (const auto &[x1, x2] : {std::pair{-0.01e-3, 0.02e-3}, std::pair{0.0, 1.0},
                                 std::pair{-1.0, 0.005e-3}, std::pair{-1.0, 1.0}}) {
      const double t1 = std::asin(std::fmax(-1.0, x1 / film.b));
      const double t2 = std::asin(std::fmin(1.0, x2 / film.b));
      const double over = film.a * film.b *
                          ((t2 + std::sin(t2) * std::cos(t2)) - (t1 + std::sin(t1) * std::cos(t1)));
      const double fd = std::erfc((film.h_min + depth) * k);
      const HertzOverPit hz = hertz_over_pit(film, PitStrip{x1, x2, depth, 0.0});
      EXPECT_NEAR(hz.metallic, (f0 * (area - over) + fd * over) / area, 1e-12);
      const double free_h =
          (1.0 - f0) * (area - over) / film.h_c + (1.0 - fd) * over / (film.h_c + depth);
      EXPECT_NEAR(hz.free_h / free_h, 1.0, 1e-11) << x1 << " " << x2;
      EXPECT_EQ(hz.min_recess, x1 < -film.b && x2 > film.b ? depth : 0.0);
    }
  // Half the ellipse over the floor, by symmetry.
  const HertzOverPit half = hertz_over_pit(film, PitStrip{0.0, 1.0, 5e-6, 0.0});
  EXPECT_NEAR(half.free_h / (0.5 * area *
                             ((1.0 - f0) / film.h_c +
                              (1.0 - std::erfc((film.h_min + 5e-6) * k)) / (film.h_c + 5e-6))),
              1.0, 1e-11);
}

TEST(PitGap, HertzZoneOverTheRoundedProfileAgainstA2DSum)
{
  // A Hertz zone wider than a narrow pit (2b = 0.5 mm, pit 0.2 mm, sag at its centre 0.8 um),
  // against the midpoint rule on a 2000 x 2000 grid over the bounding box (its error ~1e-5).
  const HertzFilm film{0.5e-6, 0.4e-6, 0.1e-6, 0.8e-3, 0.25e-3};
  const PitStrip p{-0.05e-3, 0.15e-3, 5e-6, kBall};
  const HertzOverPit hz = hertz_over_pit(film, p);
  const int n = 2000;
  const double k = 1.0 / (film.sigma * std::sqrt(2.0));
  double metal = 0.0, free_h = 0.0, area = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = film.b * (2.0 * (i + 0.5) / n - 1.0),
                   y = film.a * (2.0 * (j + 0.5) / n - 1.0);
      if (x * x / (film.b * film.b) + y * y / (film.a * film.a) > 1.0) continue;
      const double r = profile(p, x), f = std::erfc((film.h_min + r) * k);
      area += 1.0;
      metal += f;
      free_h += (1.0 - f) / (film.h_c + r);
    }
  const double cell = 4.0 * film.a * film.b / (static_cast<double>(n) * n);
  EXPECT_NEAR(hz.metallic, metal / area, 1e-5);
  EXPECT_NEAR(hz.free_h / (free_h * cell), 1.0, 1e-4);
  EXPECT_EQ(hz.min_recess, 0.0);
}

TEST(PitGap, HertzZoneWithoutEntrainmentIsDryOutsideTheStrip)
{
  // h_c = h_min = 0: the part outside the strip is metal (f = 1), the part over the floor a
  // film of the depth.
  const HertzFilm film{0.0, 0.0, 0.1e-6, 0.3e-3, 0.03e-3};
  const HertzOverPit hz = hertz_over_pit(film, PitStrip{-1.0, 1.0, 5e-6, 0.0});
  const double f = std::erfc(5e-6 / (0.1e-6 * std::sqrt(2.0)));
  EXPECT_NEAR(hz.metallic, f, 1e-15);
  EXPECT_NEAR(hz.free_h / (kPi * film.a * film.b / 5e-6), 1.0, 1e-12);
  const HertzOverPit none = hertz_over_pit(film, PitStrip{1.0, 2.0, 5e-6, 0.0});
  EXPECT_EQ(none.metallic, 1.0);
  EXPECT_EQ(none.free_h, 0.0);
  // The rounded profile is 0 at the edges: the film there goes to 0, and stays finite.
  const HertzOverPit edge = hertz_over_pit(film, PitStrip{-0.01e-3, 0.02e-3, 5e-6, kBall});
  EXPECT_TRUE(std::isfinite(edge.free_h) && edge.free_h > 0.0);
  EXPECT_TRUE(edge.metallic > 0.0 && edge.metallic <= 1.0);
}
