// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/spectrum_report.h"

#include "bearing/defect_lines.h"
#include "core/text_scan.h"

namespace ohmdem::post {

MetaList spectrum_meta(const Spectrum &s, Detrend d)
{
  return {{"spectrum", std::string("one-sided ") + scaling_name(s.scaling) +
                           (s.scaling == Scaling::Amplitude ? " (window coherent gain corrected)"
                            : s.scaling == Scaling::Psd     ? " (ENBW corrected)"
                                                            : "")},
          {"window", window_name(s.window)},
          {"detrend", detrend_name(d)},
          {"segment (samples)", std::to_string(s.segment)},
          {"segments averaged", std::to_string(s.segments)},
          {"nfft", std::to_string(s.nfft)},
          {"bin spacing (Hz)", format_number(s.df)},
          {"ENBW (Hz)", format_number(s.enbw_hz)}};
}

std::string spectrum_value_name(const Spectrum &s, const std::string &unit)
{
  const std::string vunit = s.scaling == Scaling::Amplitude ? unit
                            : unit.empty() ? std::string(s.scaling == Scaling::Psd ? "per_Hz" : "")
                                           : unit + scaling_unit(s.scaling);
  return with_unit(scaling_name(s.scaling), vunit);
}

Result spectrum_bins_result(const Spectrum &s, MetaList meta, const std::string &value_column,
                            double fmin, double fmax)
{
  Result r;
  r.meta = std::move(meta);
  r.table.columns = {"frequency_Hz", value_column};
  r.table.table_digits = 8;
  Json fs = Json::array(), vs = Json::array();  // JSON: the two columns as arrays
  for (std::size_t k = 0; k < s.bins(); ++k) {
    const double f = s.frequency(k);
    if (f < fmin || f > fmax) continue;
    r.table.rows.push_back({f, s.value[k]});
    fs.push_back(f);
    vs.push_back(s.value[k]);
  }
  r.json = Json::object();
  r.json.set("meta", meta_json(r.meta));
  r.json.set("frequency_hz", fs);
  r.json.set(value_column, vs);
  return r;
}

Result fault_band_result(const std::vector<FaultBand> &bands, MetaList meta,
                         const std::string &unit, double tolerance)
{
  Result r;
  r.meta = std::move(meta);
  r.meta.emplace_back("fault bands", "harmonic h x f, +-" + format_number(100 * tolerance) +
                                         " % (at least one bin); band power = sum of A^2/2 "
                                         "over the band / ENBW in bins");
  r.table.columns = {"label",
                     "f_low_Hz",
                     "f_high_Hz",
                     "center_Hz",
                     with_unit("peak_amplitude", unit),
                     "peak_frequency_Hz",
                     with_unit("band_power", unit.empty() ? "" : unit + "^2")};
  for (const FaultBand &b : bands)
    r.table.rows.push_back(
        {b.label, b.lo, b.hi, b.center, b.peak_amplitude, b.peak_frequency, b.power});
  return r;
}

Result spectrum_peaks_result(const std::vector<Peak> &peaks, MetaList meta,
                             const std::string &value_column, const std::string &what,
                             const PeakOptions &po, const DefectFrequencies *kin, int harmonics,
                             double tolerance)
{
  Result r;
  r.meta = std::move(meta);
  r.meta.emplace_back(
      "peaks", what + ", largest first, prominence >= " + format_number(po.min_prominence_db) +
                   " dB over the local median, " +
                   (po.interpolate ? "interpolated" : "bin values"));
  r.table.columns = {"rank", "frequency_Hz", value_column, "prominence_dB"};
  if (kin) r.table.columns.push_back("label");
  int rank = 0;
  for (const Peak &p : peaks) {
    std::vector<Cell> row{++rank, p.frequency, p.value, p.prominence_db};
    if (kin) row.emplace_back(label_frequency(p.frequency, *kin, harmonics, tolerance));
    r.table.rows.push_back(row);
  }
  return r;
}

}  // namespace ohmdem::post
