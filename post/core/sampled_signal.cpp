// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/sampled_signal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/index_line_fit.h"

namespace ohmdem::post {

std::string format_number(double v, int digits)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

namespace {
std::string at_row(const std::string &where, const RowLines &lines, std::size_t i)
{
  return i < lines.size() ? where + ":" + std::to_string(lines[i])
                          : where + " (sample " + std::to_string(i) + ")";
}
}  // namespace

Signal make_uniform(const std::vector<double> &t, std::vector<double> x, double t_resolution,
                    bool resample, const std::string &where, const RowLines &line_of_row)
{
  const std::size_t n = t.size();
  if (n != x.size()) throw Error(where + ": time and value columns differ in length");
  if (n < 2)
    throw Error(where + ": only " + std::to_string(n) +
                " sample(s); at least 2 are needed to define a sampling rate");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(t[i])) throw Error(at_row(where, line_of_row, i) + ": non-finite time");
  for (std::size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1]))
      throw Error(at_row(where, line_of_row, i) + ": time stamps not increasing (" +
                  format_number(t[i - 1], 10) + " then " + format_number(t[i], 10) + ")");
  // Uniform: every step within 1 % of the mean step, and every stamp within 1 % of a step of
  // the least-squares line through all stamps, both plus the printing resolution (a
  // difference of two rounded stamps is off by up to one rounding step). The step comes from
  // the least-squares slope, which averages the rounding out.
  const IndexLineFit line = fit_line_to_index(t.data(), n);
  const double dt_fit = line.slope;
  const double tol = 0.01 * dt_fit + t_resolution;
  std::size_t worst_step = 0, worst_line = 0;
  double step_dev = 0, line_dev = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dl = std::fabs(t[i] - line.at(i));
    if (dl > line_dev) {
      line_dev = dl;
      worst_line = i;
    }
    const double ds = i ? std::fabs(t[i] - t[i - 1] - dt_fit) : 0;
    if (ds > step_dev) {
      step_dev = ds;
      worst_step = i;
    }
  }
  const bool uniform = step_dev <= tol && line_dev <= tol;
  const std::size_t worst = step_dev > tol ? worst_step : worst_line;
  const double worst_dev = step_dev > tol ? step_dev : line_dev;
  Signal s;
  s.t0 = t[0];
  if (uniform) {
    s.rate = 1.0 / dt_fit;
    s.x = std::move(x);
    if (t_resolution > 0.1 * dt_fit)
      s.meta.emplace_back("time resolution", "stamps printed to " + format_number(t_resolution) +
                                                 " s (" + format_number(t_resolution / dt_fit, 3) +
                                                 " steps): uniformity checked within it");
    return s;
  }
  if (!resample)
    throw SettingError(
        at_row(where, line_of_row, worst) + ": non-uniform time stamps (off by " +
        format_number(worst_dev / dt_fit, 3) + " of the mean step " + format_number(dt_fit) +
        " s); pass {input.resample} to interpolate linearly onto a uniform grid, or choose "
        "a uniform part with {input.from}/{input.to}");
  std::vector<double> d(n - 1);
  for (std::size_t i = 1; i < n; ++i) d[i - 1] = t[i] - t[i - 1];
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  const double dt = d[d.size() / 2];
  const auto m = static_cast<std::size_t>(std::floor((t[n - 1] - t[0]) / dt * (1 + 1e-12))) + 1;
  std::vector<double> y(m);
  std::size_t j = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double tk = t[0] + static_cast<double>(k) * dt;
    while (j + 2 < n && t[j + 1] < tk) ++j;
    const double a = std::clamp((tk - t[j]) / (t[j + 1] - t[j]), 0.0, 1.0);
    y[k] = x[j] + a * (x[j + 1] - x[j]);
  }
  s.rate = 1.0 / dt;
  s.x = std::move(y);
  s.meta.emplace_back("resampled", "linear interpolation of " + std::to_string(n) +
                                       " non-uniform samples onto step " + format_number(dt) +
                                       " s");
  return s;
}

void require_samples(const Signal &s, std::size_t n, const std::string &what)
{
  if (s.size() < n)
    throw Error(what + " needs at least " + std::to_string(n) + " samples, the signal has " +
                std::to_string(s.size()));
}

}  // namespace ohmdem::post
