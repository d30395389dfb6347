#include "bearing.h"

#include <cmath>

#include "error.h"
#include "sampled_signal.h"

namespace ohmdem::post {

BearingGeometry bearing_preset(const std::string &name)
{
  if (name == "6208") return {"6208", 13, 0.0126, (0.0732 + 0.048) / 2, 0.0};
  if (name == "6205") return {"6205", 9, 0.007940, 0.03904, 0.0};
  throw Error("option --bearing expects 6208 or 6205, got '" + name +
              "' (or give --nb --db --dp [--beta] explicitly)");
}

std::vector<std::string> bearing_preset_names()
{
  return {"6208", "6205"};
}

void validate(const BearingGeometry &g)
{
  if (g.nb < 1) throw Error("ball count --nb must be a positive integer");
  if (!(g.db > 0)) throw Error("ball diameter --db must be > 0 (m), got " + format_number(g.db));
  if (!(g.dp > g.db))
    throw Error("pitch diameter --dp (" + format_number(g.dp) +
                " m) must exceed the ball diameter --db (" + format_number(g.db) + " m)");
  if (!(std::fabs(g.contact_angle_deg) < 90))
    throw Error("contact angle --beta must lie in (-90, 90) degrees");
}

DefectFrequencies defect_frequencies(const BearingGeometry &g, double fr)
{
  validate(g);
  if (!(fr > 0) || !std::isfinite(fr)) throw Error("shaft frequency must be > 0 Hz");
  const double pi = 3.14159265358979323846;
  const double r = g.db / g.dp * std::cos(g.contact_angle_deg * pi / 180);
  DefectFrequencies f;
  f.fr = fr;
  f.ftf = fr / 2 * (1 - r);
  f.bpfo = g.nb * f.ftf;
  f.bpfi = g.nb * fr / 2 * (1 + r);
  f.bsf = g.dp / (2 * g.db) * fr * (1 - r * r);
  return f;
}

}  // namespace ohmdem::post
