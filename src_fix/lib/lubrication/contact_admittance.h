// SPDX-License-Identifier: GPL-2.0-or-later
// The admittance Y = G + j omega C of a lubricated ball-race contact and of a bearing's
// closed form (each ball its two contacts in series, the balls in parallel). Plain C++;
// equations and sources in doc/methods/lubricated_contact.md.
#ifndef OHMDEM_LUBRICATION_CONTACT_ADMITTANCE_H
#define OHMDEM_LUBRICATION_CONTACT_ADMITTANCE_H

#include <complex>

#include "lubrication/ehl_film.h"

namespace ohmdem::lubrication {

constexpr double kEpsilon0 = 8.8541878128e-12;  // F/m (CODATA 2018)

// Clausius-Mossotti, (eps - 1)/(eps + 2) proportional to density, with the Dowson-Higginson
// density rho/rho0 = 1 + 0.6 p / (1 + 1.7 p) (p in GPa). p in Pa, >= 0.
double permittivity_at_pressure(double eps_r, double p);
// The mean of that permittivity over a Hertz ellipse of peak pressure p0 (Pa):
// 2 * int_0^1 eps(p0 t) t dt (p = p0 sqrt(1 - r^2) over the normalized ellipse), by
// 8-point Gauss-Legendre.
double hertz_mean_permittivity(double eps_r, double p0);

// The capacitance of an oil-filled gap h(x, y) = h0 + x^2/(2 rx) + y^2/(2 ry) (x rolling, y
// across), between the ellipse x^2/b^2 + y^2/a^2 = 1 (excluded; a = b = 0: nothing excluded)
// and the wetted circle x^2 + y^2 = r_wet^2: eps0 eps_r int dA / h. In the scaled polar
// coordinates x = sqrt(2 rx) s cos(phi), y = sqrt(2 ry) s sin(phi) the radial integral is a
// logarithm: eps0 eps_r sqrt(rx ry) int_0^{2 pi} ln((h0 + s_out^2)/(h0 + s_in^2)) dphi, the
// angle by the midpoint rule (spectrally accurate for this smooth periodic integrand).
struct GapGeometry {
  double h0 = 0;  // gap at the centre (m), > 0
  double rx = 0, ry = 0;
  double a = 0, b = 0;  // excluded ellipse: a across, b along the rolling direction (m)
  double r_wet = 0;     // wetted radius (m)
};
double gap_capacitance(const GapGeometry &g, double eps_r);

// Fraction of the Hertz area in metallic contact at film parameter lambda: Gaussian
// composite heights z ~ N(0, sigma) against a film h_min, the area where |z| > h_min,
// erfc(lambda / sqrt 2): 1 at lambda = 0 (the dry contact), 0.32 at 1, 0.0027 at 3.
double metallic_fraction(double lambda);

// One ball-race contact.
struct ContactInput {
  FilmInput film;          // Hamrock-Dowson inputs (load, mean entrainment speed, ...)
  double a = 0, b = 0;     // Hertz semi-axes (m): a across, b along the rolling direction
  double sigma = 0;        // composite RMS roughness (m), > 0
  double r_wet = 0;        // wetted radius around the contact (m)
  double eps_r = 0;        // at the temperature, atmospheric pressure
  double resistivity = 0;  // of the oil (ohm m)
  double g_dry = 0;        // metallic conductance of the whole Hertz area (S)
  double recess = 0;       // a pit under the contact: how far the surface falls away (m), >= 0
};

struct ContactAdmittance {
  Film film;
  double lambda = 0;
  double metallic = 0;  // metallic fraction of the Hertz area
  double c_hertz = 0;   // film capacitance of the Hertz zone (F), over its non-metallic part
  double c_outer = 0;   // oil-filled gap around it out to r_wet (F)
  double g = 0;         // metallic + leakage conductance (S)
  double gap = 0;       // smallest gap across the Hertz zone: h_min + recess (m)
  double g_dry = 0;     // the metallic path the contact conducts through if its film breaks
  double capacitance() const { return c_hertz + c_outer; }
  std::complex<double> y(double omega) const { return {g, omega * capacitance()}; }
};

// G = f g_dry + (1 - f) pi a b / (rho_oil h), C = (1 - f) eps0 eps_mean pi a b / h + the gap
// outside the ellipse with h0 = max(h_c, sigma) + recess, where h = h_c + recess and the
// metallic fraction f is that of the gap, erfc((h_min + recess) / (sigma sqrt 2)); lambda stays
// the film's. Without entrainment (h_c = 0) and without recess the contact is dry: f = 1,
// G = g_dry. recess = 0 gives exactly the contact without a pit.
ContactAdmittance contact_admittance(const ContactInput &in);

// Film breakdown (doc/methods/lubricated_contact.md "Film breakdown"). The voltage amplitude across a
// contact of admittance y_self in series with y_other (the ball's other contact) under the
// voltage amplitude v across the ball: v |y_other / (y_self + y_other)|.
double contact_voltage(std::complex<double> y_self, std::complex<double> y_other, double v);
// Whether a film of thickness h (m) breaks down under a voltage amplitude v (V) with the
// breakdown field `field` (V/m): v > field h. field <= 0: never (breakdown off).
bool film_breaks_down(double v, double h, double field);
// The contact once its film broke down: its whole Hertz area conducts through the metallic path
// (f = 1, G = g_dry, no Hertz-zone capacitance); the gap around it keeps its capacitance.
ContactAdmittance broken_down(const ContactAdmittance &c);
// A ball's two contacts in series (admittances y at omega; c and loaded: the contacts that
// press, with their films) under the voltage amplitude v across the ball: each contact whose
// voltage exceeds field * gap breaks down and y becomes broken_down's. A broken contact puts
// the ball's voltage on the other, which is judged again (the fixed point: breaking one only
// raises the other's voltage). Returns how many broke down.
int break_down_ball(std::complex<double> y[2], const ContactAdmittance c[2], const bool loaded[2],
                    double v, double field, double omega);

// A ball that does not touch a race: the capacitance of its gap to it (h0 >= sigma).
double idle_gap_capacitance(double gap, double rx, double ry, double r_wet, double eps_r,
                            double sigma);

// y1 y2 / (y1 + y2); 0 when both are 0. Inline and in real arithmetic: the bearing takes one per
// ball and step. The operations, in order, of y1 y2 conj(s) / |s|^2 in std::complex (so the same
// bits) without its products' NaN tests; libgcc's general division (__divdc3) guards against
// overflows that admittances of pF and S cannot reach.
inline std::complex<double> series(std::complex<double> y1, std::complex<double> y2)
{
  const double sr = y1.real() + y2.real(), si = y1.imag() + y2.imag();
  if (sr == 0.0 && si == 0.0) return 0.0;
  const double pr = y1.real() * y2.real() - y1.imag() * y2.imag();
  const double pi = y1.real() * y2.imag() + y1.imag() * y2.real();
  const double n = sr * sr + si * si;
  return {(pr * sr - pi * -si) / n, (pr * -si + pi * sr) / n};
}

// The bearing's impedance from its admittance Y at omega > 0.
struct Impedance {
  double z_abs = 0;       // |Z| (ohm)
  double z_phase = 0;     // arg Z (rad), -pi/2 for a capacitor
  double c_parallel = 0;  // Im Y / omega (F)
  double r_parallel = 0;  // 1 / Re Y (ohm), +inf without conduction
};
Impedance impedance(std::complex<double> y, double omega);

}  // namespace ohmdem::lubrication

#endif
