// SPDX-License-Identifier: GPL-2.0-or-later
// A race defect's size from an accelerometer record by the model's curve: the energy
// of the ring's response to one defect pass, averaged over the passes, read off a curve of the
// same energy against the size from short simulations of the same scene passed through the
// same acquisition chain. Each pass's window is centred on its strongest event (searched within
// a quarter period of where the pass is expected, so that a slipping defect frequency does not
// smear the passes); the same window half a period later (between the passes) is the
// background, whose energy is subtracted. On the simulator's vibration this energy grows
// monotonically with the pit's size, where the entry and exit events of the double impulse
// merge behind the anti-alias filter (doc/methods/size_pass_energy.md).
#ifndef OHMDEM_POST_BEARING_PASS_ENERGY_H
#define OHMDEM_POST_BEARING_PASS_ENERGY_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

struct PassEnergySettings {
  std::size_t groups = 10;   // groups of consecutive passes whose energies give the scatter
  double confidence = 0.95;  // two-sided level of the interval
  // The model's curve: pass energy (V^2 s, the record's unit squared times seconds) against the
  // size (deg), both increasing; the curve's own relative error (from simulations at sizes the
  // curve does not use), combined with the pass groups' scatter in the interval.
  std::vector<double> curve_size_deg, curve_energy;
  double curve_rel_error = 0;
};

// The passes' windows on e, a record's squared deviation from its mean (or its sum over a
// sensor's axes): each centred on the pass's strongest event (e smoothed over
// smoothing_samples), searched within a quarter period of where the period puts it from the last
// pass whose event stood out; its background the window half a period later; both +-half
// samples. energy: the window's sum of e over the rate minus the background's.
struct PassWindows {
  std::vector<std::size_t> at, background;
  std::size_t half = 0;
  std::vector<double> energy;
};
PassWindows pass_windows(const std::vector<double> &e, double rate, double f);
// Throws std::invalid_argument for settings out of range (at least 3 groups, confidence in
// (0, 1), rate and frequency > 0).
void check_pass_settings(const PassEnergySettings &s, double rate, double f);

// Per-pass energies: the window is +-period/6 around the pass's strongest event, the energy
// sum(x^2)/rate of the mean-removed record minus the same from the window half a period later
// (the background, which never overlaps a pass's window).
struct PassEnergies {
  std::vector<double> energy;  // one per pass (V^2 s)
  std::vector<double> at;      // each pass's window centre (sample index)
  double mean = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> group_mean;  // per group of consecutive passes
};
// The samples over which the squared record is smoothed to find a pass's event: 0.1 ms, at
// least one.
std::size_t smoothing_samples(double rate);
PassEnergies pass_energies(const std::vector<double> &x, double rate, double f,
                           const PassEnergySettings &s);

struct PassEnergySize {
  bool valid = false;
  std::string note;                                          // how, or why not determined
  double energy = std::numeric_limits<double>::quiet_NaN();  // mean pass energy (V^2 s)
  double energy_lo = std::numeric_limits<double>::quiet_NaN();
  double energy_hi = std::numeric_limits<double>::quiet_NaN();
  double size_deg = std::numeric_limits<double>::quiet_NaN();
  double size_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double size_hi_deg = std::numeric_limits<double>::quiet_NaN();  // NaN: open above
  std::size_t passes = 0;
};

// Size on the curve at energy e: piecewise power law (linear in log size, log energy) between
// the curve's points, the first segment's law below the first point; NaN above the last point
// or for e <= 0.
double size_on_energy_curve(const std::vector<double> &size_deg, const std::vector<double> &energy,
                            double e);

// x an acceleration sampled at `rate`; the defect's passes repeat at f (Hz); defect "inner" or
// "outer". Without a curve the energy is measured (for the model's curve) and the size is not
// determined. Throws std::invalid_argument for settings out of range.
PassEnergySize size_from_pass_energy(const std::vector<double> &x, double rate, double f,
                                     const std::string &defect, const PassEnergySettings &s);

struct Diagnosis;
struct DiagnoseOptions;
struct Signal;
struct DefectLocation;
struct RaceToSize;
// An inner defect's place on the ring from an acceleration record: under a radial load the
// passes' energy peaks when the defect meets the load direction, so the energy against the
// shaft angle at each pass gives it (bearing/load_zone_fit.h), with an interval from the
// jackknife over the passes. Needs the radial load and the record's shaft angle (o.shaft_angle);
// else l.position_note says why not. An outer defect's note is left as it is.
void place_inner_by_pass_energy(const Signal &s, const RaceToSize &r, const DiagnoseOptions &o,
                                DefectLocation &l);
// diagnose's size by this method (its accel-curve size method; the curve in o.curve_size_deg and
// o.curve_rel_area_s, its error in o.curve_rel_error): the race defect found, or
// o.assume_defect at its kinematic frequency.
DefectLocation locate_by_pass_energy(const Signal &s, const Diagnosis &found,
                                    const DiagnoseOptions &o);

}  // namespace ohmdem::post

#endif
