// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/family_combs.h"

#include <algorithm>
#include <cmath>

#include "dsp/peaks.h"

namespace ohmdem::post {

namespace {

// A matched peak counts by its prominence above the local noise floor beyond 6 dB, capped at
// 40 dB so one huge line cannot make a family. A family's score is 1 when its comb stands 12 dB
// (mean over the harmonics) above what decoy combs find by chance.
constexpr double kProminenceLow = 6, kProminenceCap = 40, kMarginFull = 12;

}  // namespace

AnalysedSpectrum analyse(const char *name, const std::vector<double> &x, double rate, double fr,
                         double tolerance, const std::vector<double> &mains_hz)
{
  SpectrumOptions o;
  o.window = WindowKind::Hann;
  o.detrend = Detrend::Mean;
  o.pad = 2;
  AnalysedSpectrum a{name, spectrum(x, rate, o), {}, {}, {}};
  std::vector<double> amp(a.s.bins());
  for (std::size_t k = 0; k < amp.size(); ++k) amp[k] = amplitude_of(a.s, k);
  const std::vector<double> floor = noise_floor(amp, default_floor_block(a.s));
  const double top = *std::max_element(amp.begin(), amp.end());
  a.prominence_db.resize(amp.size());
  for (std::size_t k = 0; k < amp.size(); ++k)
    a.prominence_db[k] =
        20 * std::log10(std::max(amp[k], 1e-300) / std::max({floor[k], top * 1e-12, 1e-300}));
  a.shaft = shaft_lines(a.prominence_db, a.s.df, fr, tolerance);
  for (double mains : mains_hz)
    a.shaft.lines += mask_harmonics(a.prominence_db, a.s.df, mains, a.shaft.mask, true);
  a.open_db = a.prominence_db;
  for (std::size_t k = 0; k < amp.size(); ++k)
    if (a.shaft.mask[k]) a.prominence_db[k] = 0;
  return a;
}

namespace {

double credit(double prominence_db)
{
  return std::clamp(prominence_db - kProminenceLow, 0.0, kProminenceCap - kProminenceLow);
}

// Most prominent bin within +-width bins of frequency f (npos if f is out of range).
std::size_t best_near(const AnalysedSpectrum &a, const std::vector<double> &prom, double f,
                      double width)
{
  const double u = f / a.s.df;
  const double lo = std::max(1.0, std::ceil(u - width));
  const double hi = std::min(static_cast<double>(a.s.bins() - 1), std::floor(u + width));
  if (!(lo <= hi)) return static_cast<std::size_t>(-1);
  std::size_t best = static_cast<std::size_t>(lo);
  for (auto k = static_cast<std::size_t>(lo); k <= static_cast<std::size_t>(hi); ++k)
    if (prom[k] > prom[best]) best = k;
  return best;
}

Evidence evidence_at(const AnalysedSpectrum &a, std::size_t k, const std::string &label,
                     double expected)
{
  Evidence e;
  e.spectrum = a.name;
  e.label = label;
  e.expected_hz = expected;
  // interpolate from the local maximum if the bin sits on a lobe's flank
  std::size_t m = k;
  while (m + 1 < a.s.bins() && a.s.value[m + 1] > a.s.value[m] && m < k + 3) ++m;
  while (m > 1 && a.s.value[m - 1] > a.s.value[m] && m + 3 > k) --m;
  const Peak p = refine_peak(a.s, m);
  e.frequency_hz = p.frequency;
  e.amplitude = p.value;
  e.prominence_db = a.prominence_db[k];
  return e;
}

std::string times(int h, const char *name)
{
  return std::to_string(h) + "x" + name;
}

// Harmonics of f0 (at most DiagnoseOptions::harmonics) whose comb, searched within the tolerance,
// and whose decoys (up to 1.3 f0) stay below the highest resolved frequency f_top.
int harmonics_below_nyquist(double f0, const DiagnoseOptions &opt, double f_top)
{
  const double reach = 1.3 * (1 + opt.tolerance) * f0;
  const double fit = std::floor(f_top / reach);
  return static_cast<int>(std::clamp(fit, 0.0, static_cast<double>(opt.harmonics)));
}

// Harmonic comb of a defect family on one spectrum: the fundamental is searched within the
// slip tolerance; each harmonic counts by its prominence; sidebands (shaft for inner, cage for
// ball) add up to a quarter.
FamilyScore comb(const AnalysedSpectrum &a, const char *defect, const char *label, double f0,
                 double sideband, const char *sb_label, int H, const DiagnoseOptions &opt,
                 bool decoy = false)
{
  // a family may not claim shaft or mains lines; a decoy sees them (they are part of how rich
  // in lines the spectrum is)
  const std::vector<double> &prom = decoy ? a.open_db : a.prominence_db;
  FamilyScore fs;
  fs.defect = defect;
  fs.label = label;
  fs.nominal_hz = f0;
  fs.spectrum = a.name;
  fs.harmonics = H;
  const double width = 1.5;  // bins around each harmonic
  const double step = a.s.df / 4;
  const int nsteps = static_cast<int>(std::ceil(opt.tolerance * f0 / step));
  double best_total = -1, best_f = f0;
  for (int i = -nsteps; i <= nsteps; ++i) {
    const double f = f0 + i * step;
    double total = 0;
    for (int h = 1; h <= H; ++h) {
      const std::size_t k = best_near(a, prom, h * f, width);
      if (k != static_cast<std::size_t>(-1)) total += credit(prom[k]);
    }
    // ties go to the candidate nearest the kinematic value
    if (total > best_total + 1e-12 ||
        (std::fabs(total - best_total) <= 1e-12 && std::fabs(f - f0) < std::fabs(best_f - f0))) {
      best_total = total;
      best_f = f;
    }
  }
  double harmonic_credit = 0, sideband_credit = 0, fsum = 0, wsum = 0;
  for (int h = 1; h <= H; ++h) {
    const std::size_t k = best_near(a, prom, h * best_f, width);
    if (k == static_cast<std::size_t>(-1)) continue;
    const double c = credit(prom[k]);
    if (c <= 0) continue;
    harmonic_credit += c;
    Evidence e = evidence_at(a, k, times(h, label), h * best_f);
    fsum += c * e.frequency_hz / h;
    wsum += c;
    fs.evidence.push_back(e);
    if (sideband <= 0) continue;
    for (int sgn : {-1, 1}) {
      const double fsb = h * best_f + sgn * sideband;
      const std::size_t ks = best_near(a, prom, fsb, width);
      if (ks == static_cast<std::size_t>(-1)) continue;
      const double cs = credit(prom[ks]);
      if (cs <= 0) continue;
      sideband_credit += cs;
      fs.evidence.push_back(
          evidence_at(a, ks, times(h, label) + (sgn < 0 ? "-" : "+") + "1x" + sb_label, fsb));
    }
  }
  // the matched fundamental: prominence-weighted mean of the interpolated harmonics
  fs.frequency_hz = wsum > 0 ? fsum / wsum : best_f;
  fs.comb = harmonic_credit / H + 0.25 * sideband_credit / (2.0 * H);
  return fs;
}

// A comb scored on a spectrum, corrected for chance matches: the same comb placed at decoy
// fundamentals f0 x r (0.7 <= r <= 1.3, |r - 1| >= 0.1) measures what a spectrum this dense in
// lines gives by chance. The family's margin is its comb value above the decoys' upper quartile.
FamilyScore family(const AnalysedSpectrum &a, const char *defect, const char *label, double f0,
                   double sideband, const char *sb_label, const DiagnoseOptions &opt)
{
  const int H = harmonics_below_nyquist(f0, opt, a.s.df * static_cast<double>(a.s.bins() - 1));
  if (H == 0) {  // even the fundamental lies beyond what the record resolves
    FamilyScore fs;
    fs.defect = defect;
    fs.label = label;
    fs.nominal_hz = fs.frequency_hz = f0;
    fs.spectrum = a.name;
    return fs;
  }
  FamilyScore fs = comb(a, defect, label, f0, sideband, sb_label, H, opt);
  std::vector<double> decoys;
  for (int i = -20; i <= 20; ++i) {
    const double r = 1 + 0.015 * i;
    if (std::fabs(r - 1) < 0.1 - 1e-9) continue;
    decoys.push_back(comb(a, defect, label, f0 * r, sideband, sb_label, H, opt, true).comb);
  }
  std::sort(decoys.begin(), decoys.end());
  fs.chance = decoys[(decoys.size() * 3) / 4];
  fs.margin = fs.comb - fs.chance;
  fs.score = std::clamp(fs.margin / kMarginFull, 0.0, 1.0);
  return fs;
}

}  // namespace

// The record's families against a healthy baseline analysed the same way: each family is
// credited only with how far its lines stand above the baseline's spectrum at the same
// frequencies (a line the baseline has as strongly adds nothing).
void relative_to_baseline(std::vector<FamilyScore> &record, const AnalysedSpectrum &base)
{
  for (FamilyScore &f : record) {
    double sum = 0;
    for (const Evidence &e : f.evidence) {
      const std::size_t k = best_near(base, base.open_db, e.frequency_hz, 2.0);
      const double b = k == static_cast<std::size_t>(-1) ? 0.0 : amplitude_of(base.s, k);
      const double ratio_db = 20 * std::log10(std::max(e.amplitude, 1e-300) / std::max(b, 1e-300));
      sum += std::clamp(ratio_db, 0.0, kProminenceCap - kProminenceLow);
    }
    f.baseline_excess = f.evidence.empty() ? 0.0 : sum / f.evidence.size();
    f.margin = std::min(f.margin, f.baseline_excess);
    f.score = std::clamp(f.margin / kMarginFull, 0.0, 1.0);
  }
}

std::vector<FamilyScore> families(const AnalysedSpectrum &a, const DefectFrequencies &k,
                                  const DiagnoseOptions &opt)
{
  // a ball defect strikes the two races in turn (2 BSF); when the two strikes differ (vibration:
  // different paths to the sensor) the ball spin frequency BSF itself shows: the better comb
  FamilyScore two = family(a, "ball", "2BSF", 2 * k.bsf, k.ftf, "FTF", opt);
  FamilyScore one = family(a, "ball", "BSF", k.bsf, k.ftf, "FTF", opt);
  return {family(a, "inner", "BPFI", k.bpfi, k.fr, "fr", opt),
          family(a, "outer", "BPFO", k.bpfo, 0, "", opt), one.margin > two.margin ? one : two,
          family(a, "cage", "FTF", k.ftf, 0, "", opt)};
}

}  // namespace ohmdem::post
