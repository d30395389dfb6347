// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/other_channel.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "dsp/envelope.h"
#include "dsp/fft.h"
#include "dsp/peaks.h"
#include "dsp/stats.h"
#include "dsp/window.h"

namespace ohmdem::post {

namespace {

// Lines that share a source are coherent (1 without noise); two independent envelopes give
// about 1 / segments by chance. Half is "mostly shared" whatever the record length.
constexpr double kCoherent = 0.5;
// A line counts when it stands this far out of its envelope spectrum's floor, and the lines
// compared are the strongest few of this channel.
constexpr double kLineDb = 10;
constexpr std::size_t kLines = 5;
// Welch segment: 1 s (1 Hz lines, apart from the slowest cage frequency), at most an eighth of
// the record so that the coherence averages enough segments.
constexpr double kSegmentSeconds = 1.0;
// "Stronger on the other channel": at least twice the excess kurtosis, and clearly impulsive
// there (0.5: the kurtosis test's threshold for a few thousand samples at 1e-3 is about 3.5).
constexpr double kStronger = 2, kImpulsive = 0.5;

double excess_kurtosis(const std::vector<double> &v)
{
  return indicators(v).kurtosis - 3;
}

struct Welch {
  std::vector<double> pxx, pyy;
  std::vector<Complex> pxy;
  double df = 0;
  std::size_t segments = 0;
};

Welch welch(const std::vector<double> &x, const std::vector<double> &y, double rate)
{
  std::size_t seg = static_cast<std::size_t>(kSegmentSeconds * rate);
  seg = std::min(seg, x.size() / 8);
  seg = std::max<std::size_t>(seg, 16);
  const std::vector<double> w = make_window(WindowKind::Hann, seg);
  Welch r;
  r.df = rate / static_cast<double>(seg);
  const std::size_t bins = seg / 2 + 1;
  r.pxx.assign(bins, 0);
  r.pyy.assign(bins, 0);
  r.pxy.assign(bins, Complex(0, 0));
  std::vector<double> a(seg), b(seg);
  std::vector<Complex> fa, fb;
  for (std::size_t start = 0; start + seg <= x.size(); start += seg / 2) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < seg; ++i) {
      ma += x[start + i];
      mb += y[start + i];
    }
    ma /= static_cast<double>(seg);
    mb /= static_cast<double>(seg);
    for (std::size_t i = 0; i < seg; ++i) {
      a[i] = (x[start + i] - ma) * w[i];
      b[i] = (y[start + i] - mb) * w[i];
    }
    rfft(a.data(), seg, fa);
    rfft(b.data(), seg, fb);
    for (std::size_t k = 0; k < bins; ++k) {
      r.pxx[k] += std::norm(fa[k]);
      r.pyy[k] += std::norm(fb[k]);
      r.pxy[k] += fa[k] * std::conj(fb[k]);
    }
    ++r.segments;
  }
  return r;
}

std::vector<double> prominence_db(const std::vector<double> &power)
{
  std::vector<double> amp(power.size());
  for (std::size_t k = 0; k < amp.size(); ++k) amp[k] = std::sqrt(power[k]);
  const std::vector<double> floor = noise_floor(amp, std::max<std::size_t>(9, amp.size() / 64));
  std::vector<double> db(amp.size());
  for (std::size_t k = 0; k < amp.size(); ++k)
    db[k] = 20 * std::log10(std::max(amp[k], 1e-300) / std::max(floor[k], 1e-300));
  return db;
}

}  // namespace

bool ChannelComparison::transmitted() const
{
  return !lines_hz.empty() && coherence >= kCoherent && other_excess >= kImpulsive &&
         other_excess >= kStronger * std::max(this_excess, 0.0);
}

std::string ChannelComparison::describe() const
{
  return std::to_string(lines_hz.size()) + " envelope lines of this channel (strongest " +
         (lines_hz.empty() ? std::string("none") : format_number(lines_hz[0], 4) + " Hz") +
         "): coherence " + format_number(coherence, 3) + " with the other channel (chance " +
         format_number(coherence_chance, 2) + "), excess kurtosis " +
         format_number(this_excess, 3) + " here, " + format_number(other_excess, 3) + " there";
}

ChannelComparison compare_channels(const std::vector<double> &x, const std::vector<double> &y,
                                   double rate, Band band, double f_lo, double f_hi)
{
  if (x.size() != y.size())
    throw SettingError("{diagnose.other_channel}: " + std::to_string(y.size()) +
                       " samples, the record has " + std::to_string(x.size()) +
                       ": the two channels must be recorded together");
  ChannelComparison c;
  c.this_excess = excess_kurtosis(x);
  c.other_excess = excess_kurtosis(y);
  const Welch w = welch(envelope(x, rate, band), envelope(y, rate, band), rate);
  c.coherence_chance = 1.0 / static_cast<double>(std::max<std::size_t>(w.segments, 1));
  const std::vector<double> px = prominence_db(w.pxx);
  // this channel's local maxima in [f_lo, f_hi] standing kLineDb out of the floor
  std::vector<std::size_t> peaks;
  for (std::size_t k = 1; k + 1 < px.size(); ++k) {
    const double f = static_cast<double>(k) * w.df;
    if (f < f_lo || f > f_hi || px[k] < kLineDb) continue;
    if (px[k] >= px[k - 1] && px[k] > px[k + 1]) peaks.push_back(k);
  }
  std::sort(peaks.begin(), peaks.end(),
            [&](std::size_t a, std::size_t b) { return px[a] > px[b]; });
  if (peaks.size() > kLines) peaks.resize(kLines);
  for (std::size_t k : peaks) {
    c.lines_hz.push_back(static_cast<double>(k) * w.df);
    c.coherence += std::norm(w.pxy[k]) / std::max(w.pxx[k] * w.pyy[k], 1e-300);
  }
  if (!peaks.empty()) c.coherence /= static_cast<double>(peaks.size());
  return c;
}

void attribute_to_other_channel(Diagnosis &d, const ChannelComparison &c, double min_score)
{
  if (d.defect != "unidentified" && d.defect != "ambiguous") return;
  if (!c.transmitted()) {
    d.warnings.push_back("other channel: " + c.describe() +
                         ": the impulses are not the other channel's");
    return;
  }
  const std::string why = "impulses from the other channel: " + c.describe();
  d.warnings.push_back(why);
  d.reason = why;
  const FamilyScore *other = nullptr;
  for (const FamilyScore &f : d.other_families)
    if (f.defect != "cage" && (!other || f.margin > other->margin)) other = &f;
  if (other && other->score >= min_score && other->shaft_order == 0) {
    d.candidate = other->defect;
    d.defect = "other-bearing";
    d.score = other->score;
    d.frequency_hz = other->frequency_hz;
    d.label = other->label;
    d.evidence = other->evidence;
    return;
  }
  d.candidate = "other channel";
  d.defect = "none";
  d.label.clear();
  d.frequency_hz = 0;
  d.evidence.clear();
}

}  // namespace ohmdem::post
