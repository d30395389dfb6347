// SPDX-License-Identifier: GPL-2.0-or-later
#include "dsp/spectrogram.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.h"
#include "core/error.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {

std::size_t spectrogram_segment(std::size_t n)
{
  std::size_t seg = 64;
  while (seg * 2 <= std::min<std::size_t>(8192, n / 64)) seg *= 2;
  return std::min(seg, n);
}

Spectrogram spectrogram(const Signal &s, const SpectrogramOptions &o)
{
  const std::size_t n = s.size();
  Spectrogram sg;
  sg.segment = std::min(o.segment ? o.segment : spectrogram_segment(n), n);
  if (sg.segment < 4)
    throw Error("spectrogram: segments of " + std::to_string(sg.segment) +
                " samples (at least 4 needed)");
  const std::size_t seg = sg.segment;
  sg.hop = std::max<std::size_t>(1, seg / 4);
  if ((n - seg) / sg.hop + 1 > o.max_columns)
    sg.hop = std::max<std::size_t>(1, (n - seg) / (o.max_columns - 1));
  const std::size_t cols = (n - seg) / sg.hop + 1;
  SpectrumOptions so;
  so.window = o.window;
  so.detrend = Detrend::Mean;
  std::vector<std::size_t> rows;  // first bin of each row (bins grouped, max taken)
  std::size_t group = 1;
  double peak_db = -INFINITY;
  std::vector<std::vector<double>> colvals;
  std::vector<double> piece(seg);
  for (std::size_t c = 0; c < cols; ++c) {
    const std::size_t start = c * sg.hop;
    std::copy(s.x.begin() + static_cast<long>(start), s.x.begin() + static_cast<long>(start + seg),
              piece.begin());
    const Spectrum sp = spectrum(piece, s.rate, so);
    if (c == 0) {
      std::size_t inside = 0;
      for (std::size_t k = 0; k < sp.bins(); ++k)
        inside += sp.frequency(k) >= o.fmin && sp.frequency(k) <= o.fmax;
      if (inside == 0)
        throw SettingError("spectrogram: no frequency bin in [" + format_number(o.fmin) + ", " +
                           format_number(o.fmax) + "] Hz ({spectrogram.fmin}, {spectrogram.fmax})");
      group = (inside + o.max_rows - 1) / o.max_rows;
      for (std::size_t k = 0; k < sp.bins(); ++k)
        if (sp.frequency(k) >= o.fmin && sp.frequency(k) <= o.fmax &&
            (rows.empty() || k >= rows.back() + group))
          rows.push_back(k);
      for (std::size_t k : rows) sg.f.push_back(sp.frequency(k));
      sg.df = sp.df;
    }
    std::vector<double> v;
    for (std::size_t k : rows) {
      double m = 0;
      for (std::size_t j = k; j < k + group && j < sp.bins(); ++j) m = std::max(m, sp.value[j]);
      v.push_back(20 * std::log10(std::max(m, 1e-300)));
      peak_db = std::max(peak_db, v.back());
    }
    colvals.push_back(v);
    sg.t.push_back(s.time(start) + 0.5 * static_cast<double>(seg) / s.rate);
  }
  sg.db.resize(sg.t.size() * sg.f.size());
  for (std::size_t c = 0; c < cols; ++c)
    for (std::size_t r = 0; r < rows.size(); ++r)
      sg.db[r * cols + c] = std::max(colvals[c][r], peak_db - o.range_db);
  return sg;
}

std::vector<double> segment_shaft_hz(const Spectrogram &sg, const std::vector<double> &theta,
                                     double rate)
{
  std::vector<double> fr;
  for (std::size_t c = 0; c < sg.t.size(); ++c) {
    const std::size_t i0 = sg.first(c), i1 = i0 + sg.segment - 1;
    fr.push_back((theta[i1] - theta[i0]) * rate / static_cast<double>(i1 - i0) / (2 * kPi));
  }
  return fr;
}

}  // namespace ohmdem::post
