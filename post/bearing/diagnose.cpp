// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/diagnose.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bearing/defect_size.h"
#include "bearing/shaft_lines.h"
#include "core/constants.h"
#include "core/error.h"
#include "dsp/peaks.h"
#include "dsp/spectrum.h"

namespace ohmdem::post {

namespace {

// A matched peak counts by its prominence above the local noise floor beyond 6 dB, capped at
// 40 dB so one huge line cannot make a family. A family's score is 1 when its comb stands 12 dB
// (mean over the harmonics) above what decoy combs find by chance.
constexpr double kProminenceLow = 6, kProminenceCap = 40, kMarginFull = 12;
// A family whose kinematic order lies within this fraction of the tolerance of an integer is
// `ambiguous` when it wins: half the search range, the part nearest the kinematic value (the
// 6203's 2 BSF, 0.3 % from 4 fr; not the 6208's BPFI, 1.9 % from 8 fr).
constexpr double kShaftCoincidence = 0.5;
// Below this kurtosis a record holds no pulse train (sine 1.5, Gaussian 3; the measured race
// faults 3.06 to 51, a healthy radially loaded 6208 at 20 kHz 2.0).
constexpr double kSmoothKurtosis = 2.5;

// A spectrum with each bin's prominence over the running-median noise floor.
struct Analysed {
  const char *name;
  Spectrum s;
  std::vector<double> prominence_db;  // shaft and mains lines masked (0 dB)
  std::vector<double> open_db;        // nothing masked: what decoy combs see
  ShaftLines shaft;                   // the shaft-harmonic lines, masked: no family may claim them
};

Analysed analyse(const char *name, const std::vector<double> &x, double rate, double fr,
                 double tolerance)
{
  SpectrumOptions o;
  o.window = WindowKind::Hann;
  o.detrend = Detrend::Mean;
  o.pad = 2;
  Analysed a{name, spectrum(x, rate, o), {}, {}, {}};
  std::vector<double> amp(a.s.bins());
  for (std::size_t k = 0; k < amp.size(); ++k) amp[k] = amplitude_of(a.s, k);
  const std::vector<double> floor = noise_floor(amp, default_floor_block(a.s));
  const double top = *std::max_element(amp.begin(), amp.end());
  a.prominence_db.resize(amp.size());
  for (std::size_t k = 0; k < amp.size(); ++k)
    a.prominence_db[k] =
        20 * std::log10(std::max(amp[k], 1e-300) / std::max({floor[k], top * 1e-12, 1e-300}));
  a.shaft = shaft_lines(a.prominence_db, a.s.df, fr, tolerance);
  for (double mains : kMainsHz)
    a.shaft.lines += mask_harmonics(a.prominence_db, a.s.df, mains, a.shaft.mask, true);
  a.open_db = a.prominence_db;
  for (std::size_t k = 0; k < amp.size(); ++k)
    if (a.shaft.mask[k]) a.prominence_db[k] = 0;
  return a;
}

double credit(double prominence_db)
{
  return std::clamp(prominence_db - kProminenceLow, 0.0, kProminenceCap - kProminenceLow);
}

// Most prominent bin within +-width bins of frequency f (npos if f is out of range).
std::size_t best_near(const Analysed &a, const std::vector<double> &prom, double f, double width)
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

Evidence evidence_at(const Analysed &a, std::size_t k, const std::string &label, double expected)
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
FamilyScore comb(const Analysed &a, const char *defect, const char *label, double f0,
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
FamilyScore family(const Analysed &a, const char *defect, const char *label, double f0,
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

// The record's families against a healthy baseline analysed the same way: each family is
// credited only with how far its lines stand above the baseline's spectrum at the same
// frequencies (a line the baseline has as strongly adds nothing).
void relative_to_baseline(std::vector<FamilyScore> &record, const Analysed &base)
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

std::vector<FamilyScore> families(const Analysed &a, const DefectFrequencies &k,
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

}  // namespace

Diagnosis diagnose(const Signal &s, const DiagnoseOptions &opt)
{
  require_samples(s, 256, "diagnose");
  if (opt.harmonics < 1 || opt.harmonics > 50)
    throw SettingError("option {diagnose.harmonics} expects 1..50");
  if (!(opt.tolerance > 0 && opt.tolerance < 0.2))
    throw SettingError("option {diagnose.tolerance} expects a fraction in (0, 0.2)");
  Diagnosis d;
  d.kinematics = defect_frequencies(opt.geometry, opt.fr);
  const DefectFrequencies &k = d.kinematics;
  const double fmax = std::max({k.bpfi, k.bpfo, 2 * k.bsf});
  const double fmin = std::min({k.bpfi, k.bpfo, k.bsf});
  // A slow instrument sees fewer harmonics (each family is scored on those below Nyquist, with
  // a warning); one that sees no race or ball fundamental cannot identify anything.
  if (1.3 * (1 + opt.tolerance) * fmin >= s.rate / 2)
    throw Error("sampling rate " + format_number(s.rate) + " Hz too low: the lowest defect " +
                "frequency " + format_number(fmin) + " Hz needs more than " +
                format_number(2.6 * (1 + opt.tolerance) * fmin) + " Hz");
  const double duration = s.duration();
  if (duration * k.ftf < 2)
    throw Error("record too short: " + format_number(duration) +
                " s holds fewer than 2 cage "
                "periods (FTF " +
                format_number(k.ftf) + " Hz)");

  std::vector<double> x = s.x;
  detrend(x.data(), x.size(), Detrend::Mean);

  // envelope band: given, or the kurtogram's best band wide enough for the combs
  d.band = opt.band;
  d.band_kurtosis = std::numeric_limits<double>::quiet_NaN();
  std::size_t bands_searched = 1;
  if (!(d.band.hi > d.band.lo)) {
    const double min_bw = std::min(s.rate / 4, 1.1 * opt.harmonics * fmax);
    const Kurtogram kg = kurtogram(x, s.rate, opt.kurtogram_levels, min_bw);
    d.band = {kg.best.lo, kg.best.hi};
    d.band_kurtosis = kg.best.kurtosis;
    bands_searched = kg.cells.size();
    d.band_kurtosis_threshold = kg.threshold;
  }

  // stage 1: detection, on the record and the band the identification uses
  DetectOptions dopt;
  dopt.false_alarm = opt.false_alarm;
  dopt.band = d.band;
  dopt.bands_searched = bands_searched;
  std::vector<double> base;
  if (opt.baseline) {
    if (std::fabs(opt.baseline->rate / s.rate - 1) > 1e-9)
      throw SettingError("{diagnose.baseline}: sampling rate " +
                         format_number(opt.baseline->rate, 10) + " Hz differs from the record's " +
                         format_number(s.rate, 10) + " Hz");
    base = opt.baseline->x;
    detrend(base.data(), base.size(), Detrend::Mean);
  }
  d.detection = detect(x, s.rate, dopt, opt.baseline ? &base : nullptr);

  // stage 2: identification; the envelope (a temporary) is freed once its spectrum is
  // analysed: lower peak memory
  const Analysed es = analyse("envelope", envelope(x, s.rate, d.band), s.rate, k.fr, opt.tolerance);
  const Analysed rs = analyse("spectrum", x, s.rate, k.fr, opt.tolerance);
  const ShaftLines &shaft = rs.shaft.comb_db >= es.shaft.comb_db ? rs.shaft : es.shaft;
  d.shaft_estimated = shaft.estimated;
  d.shaft_hz_estimated = shaft.fr;
  d.shaft_lines_masked = es.shaft.lines + rs.shaft.lines;
  auto fe = families(es, k, opt), fr = families(rs, k, opt);
  if (opt.baseline) {
    // Lines a healthy bearing has too (the ball-pass comb of a radially loaded bearing, whose
    // stiffness varies as the balls pass through the load zone) identify nothing: with a
    // baseline, a family is credited only with what its lines add to the baseline's.
    const Analysed bes =
        analyse("envelope", envelope(base, s.rate, d.band), s.rate, k.fr, opt.tolerance);
    const Analysed brs = analyse("spectrum", base, s.rate, k.fr, opt.tolerance);
    relative_to_baseline(fe, bes);
    relative_to_baseline(fr, brs);
  }
  for (std::size_t i = 0; i < fe.size(); ++i)
    d.families.push_back(fe[i].margin >= fr[i].margin ? fe[i] : fr[i]);
  for (auto &f : d.families) {
    const double order = f.nominal_hz / k.fr, n = std::round(order);
    if (n >= 1 && std::fabs(order - n) <= kShaftCoincidence * opt.tolerance * order)
      f.shaft_order = static_cast<int>(n);
  }
  for (const auto &f : d.families)
    if (f.harmonics < opt.harmonics)
      d.warnings.push_back(f.defect + " family (" + f.label + " " + format_number(f.nominal_hz) +
                           " Hz) scored on " + std::to_string(f.harmonics) + " of " +
                           std::to_string(opt.harmonics) + " harmonics: the sampling rate " +
                           format_number(s.rate) + " Hz cuts the rest");

  // inner/outer/ball compete; cage lines are also the ball's modulation, so cage is only
  // reported when no race or ball family is present
  const FamilyScore *best = nullptr;
  for (const auto &f : d.families)
    if (f.defect != "cage" && (!best || f.margin > best->margin)) best = &f;
  if (best->score < opt.min_score && d.families[3].score >= opt.min_score) best = &d.families[3];
  if (best->score >= opt.min_score) {
    d.defect = best->defect;
    d.score = best->score;
    d.frequency_hz = best->frequency_hz;
    d.label = best->label;
    d.evidence = best->evidence;
  } else {
    d.score = best->score;  // the best (insufficient) family score
    if (d.detection.fired) d.defect = "unidentified";
  }
  // A family the rate cannot see might be the one that explains the record: naming another
  // would be a guess (an inner defect sampled at 1 kHz scores as cage), so a fault stays
  // unidentified.
  for (const auto &f : d.families)
    if (f.defect != "cage" && f.harmonics == 0 && d.defect != "none" &&
        d.defect != "unidentified") {
      d.warnings.push_back("the " + f.defect + " family lies above Nyquist: " + d.defect +
                           " (score " + format_number(d.score, 3) +
                           ") cannot be told from it, reported as unidentified");
      d.defect = "unidentified";
      d.label.clear();
      d.frequency_hz = 0;
      d.evidence.clear();
      break;
    }
  // A family whose order lies within the tolerance of a shaft harmonic is not named: its lines
  // may be the machine's (the shaft lines themselves are masked, but a line beside them, of
  // the motor or of a slightly different speed, is not told apart by the comb).
  if (best->score >= opt.min_score && best->shaft_order > 0 && d.defect == best->defect) {
    d.candidate = d.defect;
    d.defect = "ambiguous";
    d.reason = best->label + " = " + format_number(best->nominal_hz / k.fr, 4) +
               " fr lies within half the tolerance (" +
               format_number(100 * kShaftCoincidence * opt.tolerance, 3) + " %) of " +
               std::to_string(best->shaft_order) + " fr: the " + d.candidate + " comb (score " +
               format_number(best->score, 3) + ") cannot be told from shaft harmonics";
    d.warnings.push_back("ambiguous: " + d.reason);
  }
  // A race comb on a record with no pulse in it: a loaded healthy bearing's stiffness varies as
  // the balls pass the load zone, a smooth modulation at BPFO (kurtosis near a sine's 1.5),
  // where a defect's pulse train is impulsive (kurtosis above a Gaussian's 3).
  const double kurt = d.detection.tests.empty() ? 3.0 : d.detection.tests[0].value;
  // With a baseline the healthy modulation is the reference already (relative_to_baseline).
  // Only on a measured record (a noise floor: the Gaussian tests apply): the simulator's
  // noise-free R(t) of a wide defect is a long rectangle train of low kurtosis too (1.66 for
  // the run-up study's inner defect), and is judged by its comb.
  if ((d.defect == "inner" || d.defect == "outer") && kurt < kSmoothKurtosis && !opt.baseline &&
      d.detection.gaussian_applicable) {
    d.candidate = d.defect;
    d.reason = "smooth modulation at " + d.label + ": kurtosis " + format_number(kurt, 3) + " < " +
               format_number(kSmoothKurtosis) +
               ", no pulse train (a loaded healthy bearing's varying compliance)";
    d.defect = d.detection.fired ? "unidentified" : "none";
    d.warnings.push_back(d.candidate + " comb not taken: " + d.reason);
  }
  // A cage verdict: FTF lines are also the modulation of a ball defect's 2 BSF comb (a ball
  // defect is weaker and less periodic than a race's): with any ball comb above chance, say so.
  if (d.defect == "cage" && d.families[2].score > 0) {
    d.candidate = "ball";
    d.reason =
        "possible ball defect: FTF lines are also the cage modulation of a ball defect "
        "(ball comb " +
        d.families[2].label + " score " + format_number(d.families[2].score, 3) + ")";
  }
  if (d.shaft_estimated) {
    d.shaft_source = "shaft comb";
  } else if (d.defect == "inner" || d.defect == "outer") {
    d.shaft_estimated = true;
    d.shaft_hz_estimated = d.frequency_hz * k.fr / best->nominal_hz;
    d.shaft_source = d.label + " comb";
  }
  d.detected = d.defect != "none";
  if (opt.estimate_size) {
    d.size = estimate_size(s, d, opt.geometry);
    d.located = locate_defect(s, d, opt);
  }
  return d;
}

}  // namespace ohmdem::post
