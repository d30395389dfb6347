// SPDX-License-Identifier: GPL-2.0-or-later
#include "bearing/diagnose.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bearing/ball_evidence.h"
#include "bearing/defect_size.h"
#include "bearing/locate/locate.h"
#include "bearing/family_combs.h"
#include "bearing/other_channel.h"
#include "bearing/pulse_train.h"
#include "bearing/shaft_lines.h"
#include "core/constants.h"
#include "core/error.h"

namespace ohmdem::post {

namespace {

// A family whose kinematic order lies within this fraction of the tolerance of an integer is
// `ambiguous` when it wins: half the search range, the part nearest the kinematic value (the
// 6203's 2 BSF, 0.3 % from 4 fr; not the 6208's BPFI, 1.9 % from 8 fr).
constexpr double kShaftCoincidence = 0.5;
// Per family, the better of its envelope and spectrum scores; shaft_order marks a family whose
// kinematic order lies within kShaftCoincidence x tolerance of a shaft harmonic.
std::vector<FamilyScore> better_of(const std::vector<FamilyScore> &fe,
                                   const std::vector<FamilyScore> &fr, double shaft_hz,
                                   double tolerance)
{
  std::vector<FamilyScore> out;
  for (std::size_t i = 0; i < fe.size(); ++i)
    out.push_back(fe[i].margin >= fr[i].margin ? fe[i] : fr[i]);
  for (auto &f : out) {
    const double order = f.nominal_hz / shaft_hz, n = std::round(order);
    if (n >= 1 && std::fabs(order - n) <= kShaftCoincidence * tolerance * order)
      f.shaft_order = static_cast<int>(n);
  }
  return out;
}

// The other bearing's best race or ball comb explains the record better than any family of this
// bearing, when none of them is named: its impulses reach this sensor through the housing.
// Not taken when its order lies near a shaft harmonic, when one of this bearing's fundamentals
// lies within the tolerance of it (the two cannot be told apart), or, on a measured record
// with no pulse in it, for a race comb (a smooth load-zone modulation, as for this bearing).
void attribute_to_other(Diagnosis &d, const DiagnoseOptions &opt, double kurt)
{
  const FamilyScore *other = nullptr;
  for (const auto &f : d.other_families)
    if (f.defect != "cage" && (!other || f.margin > other->margin)) other = &f;
  const FamilyScore *own = nullptr;
  for (const auto &f : d.families)
    if (!own || f.margin > own->margin) own = &f;
  if (!other || other->score < opt.min_score || other->margin <= own->margin) return;
  const std::string &name = opt.other->name;
  const std::string why = name + "'s " + other->label + " comb (score " +
                          format_number(other->score, 3) + ", margin " +
                          format_number(other->margin, 3) + " dB) exceeds this bearing's best (" +
                          own->label + ", margin " + format_number(own->margin, 3) + " dB)";
  if (other->shaft_order > 0) return;
  for (const auto &f : d.families)
    if (std::fabs(f.nominal_hz / other->nominal_hz - 1) <= opt.tolerance) {
      d.warnings.push_back(why + ", but lies within the tolerance of this bearing's " + f.label +
                           ": the two cannot be told apart");
      return;
    }
  const bool named = d.defect == "inner" || d.defect == "outer" || d.defect == "ball";
  if (named) {  // this bearing's own comb scores too: both may be damaged
    d.warnings.push_back(why + ": the impulses may come from the other bearing");
    return;
  }
  if (other->defect != "ball" && smooth_modulation(kurt, *other) && !opt.baseline) return;
  d.candidate = other->defect;
  d.reason = "impulses at " + name + "'s " + other->label +
             " (the other bearing on the shaft): " + "not this bearing's defect; " + why;
  d.defect = "other-bearing";
  d.score = other->score;
  d.frequency_hz = other->frequency_hz;
  d.label = other->label;
  d.evidence = other->evidence;
}

}  // namespace

Diagnosis diagnose(const Signal &s, const DiagnoseOptions &opt)
{
  require_samples(s, 256, "diagnose");
  if (opt.harmonics < 1 || opt.harmonics > 50)
    throw SettingError("option {diagnose.harmonics} expects 1..50");
  if (!(opt.tolerance > 0 && opt.tolerance < 0.2))
    throw SettingError("option {diagnose.tolerance} expects a fraction in (0, 0.2)");
  if (!(opt.speed_refine >= 0 && opt.speed_refine <= opt.tolerance))
    throw SettingError("option {diagnose.speed_refine} expects a fraction in [0, " +
                       format_number(opt.tolerance) + "] (at most {diagnose.tolerance})");
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
  const double min_bw = std::min(s.rate / 4, 1.1 * opt.harmonics * fmax);
  std::vector<std::complex<double>> band_envelope;  // the kurtogram's, for band_sk
  if (!(d.band.hi > d.band.lo)) {
    const Kurtogram kg = kurtogram(x, s.rate, opt.kurtogram_levels, min_bw, band_envelope);
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
  if (!band_envelope.empty()) dopt.band_envelope = &band_envelope;
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
  std::vector<std::complex<double>>().swap(band_envelope);

  // stage 2: identification; the envelope (a temporary) is freed once its spectrum is
  // analysed: lower peak memory
  const AnalysedSpectrum es = analyse("envelope", envelope(x, s.rate, d.band), s.rate, k.fr,
                                      opt.speed_refine, opt.mains_hz);
  const AnalysedSpectrum rs =
      analyse("spectrum", x, s.rate, k.fr, opt.speed_refine, opt.mains_hz);
  const ShaftLines &shaft = rs.shaft.comb_db >= es.shaft.comb_db ? rs.shaft : es.shaft;
  // What the spectrum says of the speed, searched within the slip tolerance on the unmasked
  // spectra: reported only (a stated speed off by a percent, the MFPT rig's; or a defect comb
  // the search locked onto), never used beyond speed_refine
  {
    const ShaftLines we = shaft_lines(es.open_db, es.s.df, opt.fr, opt.tolerance);
    const ShaftLines wr = shaft_lines(rs.open_db, rs.s.df, opt.fr, opt.tolerance);
    const ShaftLines &wide = wr.comb_db >= we.comb_db ? wr : we;
    d.shaft_estimated = wide.estimated;
    d.shaft_hz_estimated = wide.fr;
  }
  if (!d.shaft_estimated && shaft.estimated) {
    d.shaft_estimated = true;
    d.shaft_hz_estimated = shaft.fr;
  }
  d.shaft_lines_masked = es.shaft.lines + rs.shaft.lines;
  // the kinematics at the speed used: the stated one, refined by a strong shaft comb
  d.shaft_refined = shaft.estimated && shaft.fr != opt.fr;
  d.shaft_hz_used = shaft.estimated ? shaft.fr : opt.fr;
  d.kinematics = defect_frequencies(opt.geometry, d.shaft_hz_used);
  auto fe = families(es, k, opt), fr = families(rs, k, opt);
  std::vector<FamilyScore> oe, orr;
  if (opt.other) {
    d.other_kinematics = defect_frequencies(*opt.other, d.shaft_hz_used);
    oe = families(es, d.other_kinematics, opt);
    orr = families(rs, d.other_kinematics, opt);
  }
  if (opt.baseline) {
    // Lines a healthy bearing has too (the ball-pass comb of a radially loaded bearing, whose
    // stiffness varies as the balls pass through the load zone) identify nothing: with a
    // baseline, a family is credited only with what its lines add to the baseline's.
    const AnalysedSpectrum bes = analyse("envelope", envelope(base, s.rate, d.band), s.rate, k.fr,
                                         opt.speed_refine, opt.mains_hz);
    const AnalysedSpectrum brs =
        analyse("spectrum", base, s.rate, k.fr, opt.speed_refine, opt.mains_hz);
    for (auto *v : {&fe, &oe}) relative_to_baseline(*v, bes);
    for (auto *v : {&fr, &orr}) relative_to_baseline(*v, brs);
  }
  d.families = better_of(fe, fr, k.fr, opt.tolerance);
  d.other_families = better_of(oe, orr, k.fr, opt.tolerance);
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
  // a ball and a race comb on the same lines: the FTF modulation decides (ball_evidence.h)
  std::string overlap;
  if (best->score >= opt.min_score) best = ball_or_race(d.families, best, opt.tolerance, overlap);
  if (!overlap.empty()) d.warnings.push_back(overlap);
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
  // A ball comb deeply modulated at FTF is the exception: shaft lines carry no cage modulation.
  const CageModulation cage_mod = cage_modulation(d.families);
  const bool ball_modulated = best->defect == "ball" && cage_mod.present();
  // A race comb is the other exception when it sits at its kinematic value, nearer to it than
  // halfway to the shaft harmonic: a race defect barely slips and the speed is the stated one
  // (within speed_refine), where lines beside a shaft harmonic would have drawn the comb's
  // search toward it
  const bool race = best->defect == "inner" || best->defect == "outer";
  const double off_kinematic = std::fabs(best->frequency_hz / best->nominal_hz - 1);
  const double to_shaft = std::fabs(best->shaft_order * k.fr / best->nominal_hz - 1);
  const bool race_at_kinematic = race && best->shaft_order > 0 && off_kinematic < 0.5 * to_shaft;
  if (best->score >= opt.min_score && best->shaft_order > 0 && d.defect == best->defect &&
      race_at_kinematic)
    d.warnings.push_back(best->label + " = " + format_number(best->nominal_hz / k.fr, 4) +
                         " fr lies near " + std::to_string(best->shaft_order) +
                         " fr, but the comb lies " + format_number(100 * off_kinematic, 3) +
                         " % from its kinematic value, " + format_number(100 * to_shaft, 3) +
                         " % from the shaft harmonic: reported as " + best->defect);
  else if (best->score >= opt.min_score && best->shaft_order > 0 && d.defect == best->defect &&
           ball_modulated)
    d.warnings.push_back(best->label + " = " + format_number(best->nominal_hz / k.fr, 4) +
                         " fr lies near " + std::to_string(best->shaft_order) +
                         " fr, but the comb is modulated at FTF (" + cage_mod.describe() +
                         "), which shaft lines are not: reported as ball");
  else if (best->score >= opt.min_score && best->shaft_order > 0 && d.defect == best->defect) {
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
  // A second discriminator, independent of the kurtosis (pulse_train.h): a pulse train's comb
  // keeps its harmonics, a smooth modulation's falls fast; a weak defect whose kurtosis lies
  // within its sampling error of 3 is still taken when its comb is a pulse train's. Both hold
  // on a record without a noise floor too, where the kurtosis is a shape, not a test. There,
  // under a radial load, the kurtosis alone decides: the simulator's R of a healthy radial
  // 6208 at 1 MHz has kurtosis 1.99 (a 1-degree pit's: 110), its balls entering the load zone
  // steps whose envelope comb keeps its harmonics (0.85); under a balanced load a healthy
  // bearing has no such modulation, and a wide defect's low kurtosis comb is its own.
  const bool noise_free_smooth =
      !d.detection.gaussian_applicable && opt.load == "radial" && kurt < kSmoothKurtosis;
  if ((d.defect == "inner" || d.defect == "outer") &&
      (smooth_modulation(kurt, *best) || noise_free_smooth) && !opt.baseline) {
    d.candidate = d.defect;
    const double ratio = harmonic_ratio(*best);
    d.reason = "smooth modulation at " + d.label + ": kurtosis " + format_number(kurt, 3) + " < " +
               format_number(kSmoothKurtosis) +
               (smooth_modulation(kurt, *best)
                    ? " and comb harmonics " +
                          (std::isfinite(ratio) ? format_number(ratio, 3)
                                                : std::string("(too few)")) +
                          " of the fundamental < " + format_number(kPulseHarmonics)
                    : " on a record without a noise floor under a radial load") +
               ", no pulse train (a loaded healthy bearing's varying compliance)";
    d.defect = d.detection.fired ? "unidentified" : "none";
    d.warnings.push_back(d.candidate + " comb not taken: " + d.reason);
  }
  if (opt.other) attribute_to_other(d, opt, kurt);
  // A cage verdict: FTF lines are also the modulation of a ball defect's 2 BSF comb (a ball
  // defect is weaker and less periodic than a race's): with any ball comb above chance, say so.
  if (d.defect == "cage" && d.families[2].score > 0) {
    d.candidate = "ball";
    d.reason =
        "possible ball defect: FTF lines are also the cage modulation of a ball defect "
        "(ball comb " +
        d.families[2].label + " score " + format_number(d.families[2].score, 3) + ")";
  }
  if (opt.other_channel) {  // after every rule of this channel: only a flagged record changes
    if (std::fabs(opt.other_channel->rate / s.rate - 1) > 1e-9)
      throw SettingError("{diagnose.other_channel}: sampling rate " +
                         format_number(opt.other_channel->rate, 10) +
                         " Hz differs from the record's " + format_number(s.rate, 10) + " Hz");
    std::vector<double> y = opt.other_channel->x;
    detrend(y.data(), y.size(), Detrend::Mean);
    const ChannelComparison c = compare_channels(x, y, s.rate, d.band, 0.9 * k.ftf, min_bw);
    attribute_to_other_channel(d, c, opt.min_score);
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
    d.located = locate(s, d, opt);
  }
  return d;
}

}  // namespace ohmdem::post
