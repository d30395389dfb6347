// SPDX-License-Identifier: GPL-2.0-or-later
// Defect diagnosis in two stages: detection (is the record unlike a healthy one: detect.h), then
// identification: peaks of the spectrum and of the envelope spectrum matched against the
// bearing's defect families (harmonic combs with shaft/cage sidebands, a tolerance for slip),
// the most likely defect with a score and its evidence, and the defect size from pulse widths.
#ifndef OHMDEM_POST_DIAGNOSE_H
#define OHMDEM_POST_DIAGNOSE_H

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "bearing/locate/defect_location.h"
#include "core/sampled_signal.h"
#include "dsp/butterworth.h"
#include "dsp/detect.h"
#include "dsp/envelope.h"

namespace ohmdem::post {

struct TemplateBank;  // bearing/pulse_template.h
class SizeMethod;    // bearing/locate/size_method.h
class PlaceMethod;   // bearing/locate/place_method.h

struct DiagnoseOptions {
  BearingGeometry geometry;
  double fr = 0;            // shaft frequency (Hz), as stated (run.json, option, tachometer)
  // The spectrum's shaft comb may move the stated speed by at most this fraction, and only
  // where the comb is strong (shaft_lines.h): a stated speed is the truth, or close to it for
  // a tachometer; a comb searched wider locks onto a defect's lines (the 6208's BPFI lies
  // 1.9 % from 8 fr: an inner pit's comb taken for the shaft's 8th harmonic, then masked)
  double speed_refine = 0.002;
  double tolerance = 0.02;  // fundamental searched within +-tolerance (relative) for slip
  int harmonics = 5;        // comb length
  double min_score = 0.3;   // below: defect "none"
  Band band;                // envelope band; lo = hi = 0: chosen by the kurtogram
  int kurtogram_levels = 7;
  bool estimate_size = true;
  // the size and place methods (locate/size_method.h); null: chosen by the record
  const SizeMethod *size_method = nullptr;
  const PlaceMethod *place_method = nullptr;
  // the size from the pulses' area: the load mode ("force", "fixed", "radial"; empty:
  // unknown), the relative level jump of one lost ball path (0: the theory of a balanced load,
  // 1 / (Nb - 1), none under a radial load), the shaft angle per sample (rad) or null
  std::string load;
  double pulse_height = 0;
  const std::vector<double> *shaft_angle = nullptr;
  // the record's anti-alias filter's delay at 0 Hz (s; its header's lowpass line), 0 when it
  // states none: an event's time in the record is this much after the event (in the angle
  // domain, revolutions: diagnose_in_orders converts it at the mean speed)
  double record_delay_s = 0;
  // that filter itself, when the header states it: the accelerometer's events are delayed by
  // its group delay where their energy lies, not at 0 Hz (bearing/pass_energy.h)
  std::optional<RecordFilter> record_filter;
  // "inner" or "outer": size and place that defect (at its kinematic frequency, refined by the
  // pulses) whatever the identification says; empty: the identified defect only
  std::string assume_defect;
  // the model's curve (bearing/pulse_area.h): sizes (deg) and fixed-window areas / level (s)
  std::vector<double> curve_size_deg, curve_rel_area_s;
  // the curve's own error: relative standard deviation of its area (0: the interval is the
  // pass-to-pass scatter only)
  double curve_rel_error = 0;
  // the model's width curve (bearing/pulse_edges.h): sizes (deg) and entry-to-exit widths (s),
  // through the record's chain; where the record's width lies on it, the size is read off it
  std::vector<double> width_curve_size_deg, width_curve_s;
  double width_rel_error = 0;        // its own relative error, as curve_rel_error
  // the model's pulse templates (bearing/pulse_template.h) for the template-fit size, or none
  const TemplateBank *template_bank = nullptr;
  // the record's fold (the template fit's, and the one written out) at the period of
  // refine_repetition_fine instead of the grid's (pulse_template.h FoldPeriod); a bank states
  // its own
  bool fine_fold_period = false;
  double false_alarm = 1e-3;         // per detection test
  const Signal *baseline = nullptr;  // healthy reference record (same rate), or none
  // Mains frequencies (Hz) whose harmonic combs are masked where they stand out (the supply's
  // lines at exact multiples); empty: none
  std::vector<double> mains_hz{50, 60};
  // The other bearing on the same shaft (the CWRU fan-end sensor hears the drive-end bearing):
  // its families are scored on the same spectra, so that a record whose impulses are at one of
  // ITS defect frequencies reads `other-bearing` instead of `unidentified`
  std::optional<BearingGeometry> other;
  // The other bearing's sensor, recorded with this one (same rate and samples), or none: a
  // flagged record whose impulses are coherent with it and stronger there reads `none`
  // (impulses from the other channel) or `other-bearing` (other_channel.h)
  const Signal *other_channel = nullptr;
  // The accelerometer's second axis, recorded with this one (same rate and samples), at right
  // angles to it in the bearing's plane (the record's axis turned +90 deg), or none: with the
  // record's axis along the load direction, an outer defect's angle from it (event_direction.h)
  const Signal *across = nullptr;
};

struct Evidence {
  std::string spectrum;      // "envelope" or "spectrum"
  std::string label;         // "1xBPFI", "2xBPFO", "1xBPFI+1xfr", ...
  double expected_hz = 0;    // h x matched fundamental (+- sideband)
  double frequency_hz = 0;   // peak found (interpolated)
  double amplitude = 0;      // in the signal's unit
  double prominence_db = 0;  // above the local noise floor
};

struct FamilyScore {
  std::string defect;       // inner, outer, ball, cage
  std::string label;        // the comb's fundamental: BPFI, BPFO, 2BSF or BSF, FTF
  double nominal_hz = 0;    // kinematic fundamental
  double frequency_hz = 0;  // matched fundamental (best comb within the tolerance)
  double score = 0;         // 0..1: margin / 12 dB, clamped
  double comb = 0;          // mean prominence credit of the harmonics (dB over 6 dB, capped
                            // at 34) + a quarter of the sidebands' mean credit
  double chance = 0;        // upper quartile of the same comb at decoy fundamentals (dB)
  double margin = 0;        // comb - chance (dB); with a baseline, at most baseline_excess
  // With a baseline: the mean over the evidence lines of how far (dB, 0..34) each stands
  // above the baseline's spectrum at the same frequency; NaN without a baseline.
  double baseline_excess = std::numeric_limits<double>::quiet_NaN();
  std::string spectrum;  // which spectrum gave the score
  // n when the kinematic fundamental is within half the tolerance of the shaft harmonic n fr
  // (n >= 1; the comb search could slide onto it), else 0: the family can only be `ambiguous`
  int shaft_order = 0;
  // harmonics scored: DiagnoseOptions::harmonics, fewer when the comb (and its decoys, up to 1.3 x)
  // would pass Nyquist; 0 when even the fundamental does (the family cannot be seen at this rate)
  int harmonics = 0;
  std::vector<Evidence> evidence;
};

struct SizeEstimate {
  bool valid = false;
  std::string method;  // "pulses" (direct), "synchronous average", or why not
  double pulse_width_s = 0;
  double size_deg = 0;  // angular extent on the race (inner/outer) or on the ball
  double arc_m = 0;     // the same as an arc length
  std::size_t pulses = 0;
};

struct Diagnosis {
  // inner, outer, ball or cage when a family scores >= min_score; else "unidentified" when the
  // detection stage fired (a fault of unknown type); else "none"
  std::string defect = "none";
  // "ambiguous": the best family scored but its fundamental lies within the
  // tolerance of a shaft harmonic (2 BSF = 3.988 fr for the CWRU fan-end 6203), where its comb
  // cannot be told from the machine's shaft lines; candidate names it and reason says why.
  // With "cage": candidate "ball" when a ball comb scores above chance too (possible ball
  // defect, the reason says so). With "none"/"unidentified": the race family whose comb was not
  // taken because the record holds no pulse (pulse_train.h: a smooth load-zone modulation); with
  // "none", "other channel" when the impulses are the other sensor's (other_channel.h).
  std::string candidate, reason;
  bool detected = false;  // a family identified or a detection test fired
  Detection detection;
  double score = 0;
  double frequency_hz = 0;  // matched fundamental of the reported family (0 for none)
  std::string label;        // what frequency_hz is: BPFI, BPFO, 2BSF, BSF or FTF
  std::vector<Evidence> evidence;
  std::vector<FamilyScore> families;  // inner, outer, ball, cage
  DefectFrequencies kinematics;
  Band band;                 // envelope band used
  double band_kurtosis = 0;  // spectral kurtosis of that band (kurtogram), NaN if given
  // Gaussian-noise level of the kurtogram's best band at alpha = 0.01 over the bands searched
  // (Kurtogram::threshold), NaN if the band was given
  double band_kurtosis_threshold = std::numeric_limits<double>::quiet_NaN();
  bool band_kurtosis_significant() const { return band_kurtosis > band_kurtosis_threshold; }
  SizeEstimate size;  // the pulse width measured (the area method checks its jump with it)
  DefectLocation located;
  // The shaft frequency from the spectrum's shaft harmonics (shaft_lines.h; the spectrum whose
  // shaft comb is stronger), searched within the tolerance, when they stand out: reported, used
  // only through shaft_hz_used (within speed_refine); the lines of the speed used masked (both
  // spectra) so that no defect comb claims them.
  // Without a shaft comb, an identified race family gives it (matched / kinematic order: race
  // defects barely slip); shaft_source says which: "shaft comb" or "BPFI comb", "BPFO comb".
  bool shaft_estimated = false;
  double shaft_hz_estimated = 0;
  std::string shaft_source;
  // The shaft frequency the kinematics used (Hz): the stated one, moved by the shaft comb
  // within DiagnoseOptions::speed_refine when its comb stands out (shaft_refined)
  double shaft_hz_used = 0;
  bool shaft_refined = false;
  std::size_t shaft_lines_masked = 0;
  std::vector<std::string> warnings;  // e.g. families the sampling rate cuts short
  // With DiagnoseOptions::other: that bearing's kinematics and families on the same spectra.
  // defect "other-bearing" (candidate: its family, reason: why) when no family of this bearing
  // is named and the other's best race or ball comb scores >= min_score with a larger margin than
  // any of this bearing's; frequency_hz, label and evidence are then the other's.
  DefectFrequencies other_kinematics;
  std::vector<FamilyScore> other_families;
};

Diagnosis diagnose(const Signal &s, const DiagnoseOptions &opt);

// Angular defect size from a pulse width tau and the matched fundamental f:
// inner race (omega_inner - omega_cage) tau = 2 pi f tau / Nb, outer race omega_cage tau =
// 2 pi f tau / Nb, ball 2 pi BSF tau = pi f tau (f = 2 BSF). Radians.
double defect_angle(const std::string &defect, double f, double tau, int nb);

}  // namespace ohmdem::post

#endif
