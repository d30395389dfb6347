// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricated bearing's per-step arithmetic in two variants of one interface, chosen by name
// (compute network/resistance's keyword `kernel`):
//   plain  one contact at a time in scalar code: the reference;
//   lanes  a ball's two contacts two doubles per operation, a race's films four or eight at a
//          time (race_admittance_batch.cpp), every result the plain kernel's bit for bit
//          (tests/lib/lubrication: test_bearing_kernels.cpp, test_race_admittance_batch.cpp).
// Each is a struct of static functions, so that the bearing's loop, a template on the kernel,
// inlines them: no call through a pointer per ball.
#ifndef OHMDEM_LUBRICATION_BEARING_KERNELS_H
#define OHMDEM_LUBRICATION_BEARING_KERNELS_H

#include <array>
#include <complex>
#include <string>

#include "lubrication/contact_admittance.h"
#include "lubrication/race_admittance.h"

namespace ohmdem::lubrication {

// A race's rigid motion on one step: centre (m), angular speed (rad/s), centre velocity (m/s).
struct RaceFrame {
  double cx = 0, cy = 0, w = 0, vcx = 0, vcy = 0;
};

// A ball in the plane: centre x and velocity v (m, m/s; x[0], x[1] and v[0], v[1] read), spin
// omega_z (rad/s), and its contact points with the two races (px[s], py[s], side s).
struct BallMotion {
  const double *x = nullptr, *v = nullptr;
  double omega_z = 0;
  double px[2] = {0, 0}, py[2] = {0, 0};
};

using RaceMinima = std::array<RaceAdmittance::Minima, 2>;

// The mean entrainment speed of a ball-race contact at point p: the tangential component of
// the mean of the two surfaces' velocities, relative to the contact point, which travels with
// the ball's orbit about the ring centre c. Pure rolling on a fixed outer ring gives
// (omega_i - omega_cage) R_i at the inner contact. With n = p - x (ball centre to contact), the
// tangent t = (-n_y, n_x) (|t| = |n|) and d = n . (p - c), the three velocities' tangential
// parts are t . ball = -n_y v_x + n_x v_y + omega_z |n|^2, t . ring = -n_y vc_x + n_x vc_y + w d
// and t . orbit = Omega d, so
//   |n| u = 1/2 (-n_y (v_x + vc_x) + n_x (v_y + vc_y) + omega_z |n|^2 + w d) - Omega d,
// Omega = (o x v) / |o|^2 the orbit's rate (o = x - c).
double entrainment_speed(const BallMotion &ball, int side, const RaceFrame &race);

struct PlainKernel {
  static constexpr const char *kName = "plain";
  // Both sides' entrainment speeds (a race the ball does not press: computed, not used).
  static std::array<double, 2> speeds(const BallMotion &ball, const RaceFrame race[2])
  {
    return {entrainment_speed(ball, 0, race[0]), entrainment_speed(ball, 1, race[1])};
  }
  // The two races' pressed contacts: out_a[k] = a.contact(in_a's k-th inputs), and b's; each
  // race's smallest film.minimum and lambda.
  static RaceMinima contacts(const RaceAdmittance &a, const ContactBatch &in_a,
                             ContactAdmittance *out_a, const RaceAdmittance &b,
                             const ContactBatch &in_b, ContactAdmittance *out_b);
  // A ball's two contacts in series (y = G + j omega C).
  static std::complex<double> series(std::complex<double> y1, std::complex<double> y2)
  {
    return lubrication::series(y1, y2);
  }
};

struct LanesKernel {
  static constexpr const char *kName = "lanes";
  static std::array<double, 2> speeds(const BallMotion &ball, const RaceFrame race[2]);
  static RaceMinima contacts(const RaceAdmittance &a, const ContactBatch &in_a,
                             ContactAdmittance *out_a, const RaceAdmittance &b,
                             const ContactBatch &in_b, ContactAdmittance *out_b)
  {
    return RaceAdmittance::contacts(a, in_a, out_a, b, in_b, out_b);
  }
  static std::complex<double> series(std::complex<double> y1, std::complex<double> y2);
};

// The kernels by name, for the keyword and its error message.
enum class BearingKernel { plain, lanes };
constexpr const char *kBearingKernelNames = "plain or lanes";
// The kernel of that name; false for a name that is none.
bool bearing_kernel_named(const std::string &name, BearingKernel &kernel);
const char *bearing_kernel_name(BearingKernel kernel);

}  // namespace ohmdem::lubrication

#endif
