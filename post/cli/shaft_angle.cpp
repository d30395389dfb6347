// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/shaft_angle.h"

#include <cmath>
#include <utility>

#include "cli/common.h"
#include "core/error.h"
#include "dsp/tacho_angle.h"
#include "io/load_signal.h"

namespace ohmdem::post::cli {

namespace {

// The column `name` over the samples of `s` (same options, window from s's time stamps).
Signal companion_column(const Args &a, const RunMetadata &meta, const Signal &s,
                        const std::string &name)
{
  InputOptions o = input_options(a);
  o.column = name;
  o.min_samples = 2;
  o.from = s.t0 - 0.5 / s.rate;
  o.to = s.time(s.size() - 1) + 0.5 / s.rate;
  Signal c = load_named(o, meta);
  if (c.size() != s.size() || std::fabs(c.t0 - s.t0) > 0.5 / s.rate)
    throw Error("column " + name + ": " + std::to_string(c.size()) + " samples from " +
                format_number(c.t0) + " s do not line up with the signal's " +
                std::to_string(s.size()) + " from " + format_number(s.t0) + " s");
  return c;
}

}  // namespace

void add_shaft_angle_options(Args &a)
{
  a.section("Shaft angle (order tracking)");
  a.option("--angle-column", "NAME|N",
           "column (or MAT variable) holding the shaft angle in rad, accumulated (default: "
           "angle_inner when present)");
  a.option("--speed-column", "NAME|N",
           "column (or MAT variable) holding the shaft speed, integrated to the angle "
           "(cumulative trapezoid); unit --speed-unit");
  a.option("--speed-unit", "UNIT", "unit of --speed-column: rad/s | rpm | hz", "rad/s");
  a.option("--tacho-column", "NAME|N",
           "column (or MAT variable) of a once-per-revolution pulse train (tachometer, "
           "keyphasor): the shaft angle is 0 at each pulse's rising edge, linear between them");
  a.option("--tacho-ppr", "N",
           "pulses per revolution of the --tacho-column (a toothed wheel, an encoder: 1..10000); "
           "the angle turns 2 pi / N from one rising edge to the next",
           "1");
}

std::optional<ShaftAngle> measured_shaft_angle(const Args &a, const RunMetadata &meta,
                                               const Signal &s)
{
  if (a.has("--angle-column") + a.has("--speed-column") + a.has("--tacho-column") > 1)
    throw Error("give the shaft angle once: --angle-column, --speed-column or --tacho-column");
  const SpeedUnit unit = parse_speed_unit(a.get("--speed-unit"));
  ShaftAngle sa;
  if (a.has("--tacho-ppr") && !a.has("--tacho-column"))
    throw Error("--tacho-ppr gives the pulses per revolution of a --tacho-column: give the column");
  if (a.has("--tacho-column")) {
    const long long ppr = a.integer_in("--tacho-ppr", 1, 1, 10000, "a pulse count per revolution");
    const Signal c = companion_column(a, meta, s, a.get("--tacho-column"));
    TachoAngle t;
    try {
      t = angle_from_tacho(c.x);
    } catch (const Error &e) {
      throw Error("--tacho-column " + c.name + ": " + e.what());
    }
    sa.theta = std::move(t.theta);
    for (double &th : sa.theta) th /= static_cast<double>(ppr);
    sa.source = "column " + c.name + ", " + std::to_string(t.pulses) +
                (ppr == 1 ? std::string(" once-per-revolution pulses (0 at each rising edge)")
                          : " pulses at " + std::to_string(ppr) +
                                " per revolution (--tacho-ppr; 0 at the first rising edge)");
  } else if (a.has("--speed-column")) {
    const Signal c = companion_column(a, meta, s, a.get("--speed-column"));
    std::vector<double> w = c.x;
    for (double &v : w) v = to_rad_per_s(v, unit);
    sa.theta = angle_from_speed(w, s.rate);
    sa.source =
        "column " + c.name + " (" + speed_unit_name(unit) + "), integrated (cumulative trapezoid)";
  } else {
    std::string name = a.get("--angle-column");
    if (name.empty()) {
      // our signal.txt: angle_inner, if the file has it (any error means it has not)
      if (a.positional().empty() || a.get("--input") == "mat") return std::nullopt;
      try {
        sa.theta = companion_column(a, meta, s, "angle_inner").x;
      } catch (const Error &) {
        return std::nullopt;
      }
      name = "angle_inner";
    } else {
      const Signal c = companion_column(a, meta, s, name);
      sa.theta = c.x;
      name = c.name;
    }
    sa.source = "column " + name + " (rad)";
  }
  sa.speed = speed_summary(sa.theta, s.rate);
  return sa;
}

ShaftAngle constant_shaft_angle(const Signal &s, double fr, const std::string &source)
{
  ShaftAngle sa;
  sa.theta = constant_speed_angle(s.size(), s.rate, fr);
  sa.source = "constant speed " + format_number(fr, 8) + " Hz (" + source + ")";
  sa.speed = speed_summary(sa.theta, s.rate);
  return sa;
}

}  // namespace ohmdem::post::cli
