// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/envelope_report.h"

#include "core/text_scan.h"

namespace ohmdem::post {

std::string kurtogram_significance(const Kurtogram &kg)
{
  return std::string(kg.significant ? "yes" : "no") + " (threshold " +
         format_number(kg.threshold, 4) + ": a Gaussian record's best band exceeds it with " +
         "probability " + format_number(kg.alpha) + "; " + std::to_string(kg.best.samples) +
         " envelope samples, " + std::to_string(kg.cells.size()) + " bands searched)";
}

Result kurtogram_result(const Kurtogram &kg, MetaList meta)
{
  Result r;
  r.meta = std::move(meta);
  r.meta.emplace_back("spectral kurtosis",
                      "E|c|^4/(E|c|^2)^2 - 2 of the band's complex "
                      "envelope (0 for Gaussian noise)");
  r.meta.emplace_back("best band (Hz)",
                      format_number(kg.best.lo) + " to " + format_number(kg.best.hi));
  r.meta.emplace_back("band kurtosis significant", kurtogram_significance(kg));
  r.table.columns = {"bands", "f_low_Hz", "f_high_Hz", "center_Hz", "spectral_kurtosis"};
  for (const auto &c : kg.cells)
    r.table.rows.push_back({c.bands, c.lo, c.hi, (c.lo + c.hi) / 2, c.kurtosis});
  return r;
}

Result envelope_result(const Signal &s, const std::vector<double> &env, const std::string &unit,
                       MetaList meta)
{
  Result r;
  r.meta = std::move(meta);
  r.meta.emplace_back("envelope", "|analytic signal| of the band-passed signal");
  r.table.columns = {"time_s", with_unit("envelope", unit)};
  for (std::size_t i = 0; i < env.size(); ++i) r.table.rows.push_back({s.time(i), env[i]});
  r.table.table_digits = 10;
  return r;
}

}  // namespace ohmdem::post
