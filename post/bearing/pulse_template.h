// SPDX-License-Identifier: GPL-2.0-or-later
// A race defect's size from the whole SHAPE of its pulse: the record is folded at the
// defect frequency on a grid finer than its samples (the passes fall at non-commensurate
// sub-sample phases, so the fold recovers the band-limited pulse at sub-sample resolution:
// equivalent-time sampling), with each bin's standard error from the scatter of the samples that
// fell in it. A bank of the same folds from short simulations of the same scene at known sizes
// (and, for an outer pit under a radial load, angles from the load direction), each passed
// through the record's own acquisition chain, is fitted to it: each template shifted in time
// (sub-bin) and offset by a constant; the size is the vertex of the parabola through the least
// weighted squared misfit and its neighbours (the angle likewise). The interval is the profile's
// rise of the chi-square quantile, scaled by the fit's reduced chi-square when above 1 (a misfit
// the pass scatter does not explain), then widened by the bank's own error (held-out simulated
// sizes).
//
// Where the area saturates (a ring free to move undoes the jump within ~100 us) the shape still
// changes with the size: the exit's strike moves, the dip after the return deepens. Where it does
// not, the profile is flat over the sizes and the interval says so.
#ifndef OHMDEM_POST_BEARING_PULSE_TEMPLATE_H
#define OHMDEM_POST_BEARING_PULSE_TEMPLATE_H

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace ohmdem::post {

// Fine bins per sample of the fold: 4 keeps ~30 samples per bin over 130 passes (0.3 s).
constexpr int kTemplateOversample = 4;

// The fold's period: refine_repetition's grid (the committed banks' folds: up to 1/40 of a
// period of drift over the record, a smear of the fold that differs from record to record), or
// refined further on the harmonics' power (refine_repetition_fine: under 1/10^4).
enum class FoldPeriod { grid, fine };

// The record folded at its defect period, relative to its level (x / mean - 1), rotated so
// that the pulse's entry (the largest rise over one sample) lies at a quarter of the period.
struct FoldedPulse {
  bool valid = false;
  std::string note;         // why not
  double bin_s = 0;         // width of a bin (s): 1 / (rate x oversample)
  double period_s = 0;      // the refined defect period (s)
  FoldPeriod how = FoldPeriod::grid;  // how it was refined
  std::size_t passes = 0;   // defect passes folded
  std::size_t entry = 0;    // the entry's bin (a quarter of the bins)
  // bins no pass fell in (a period near a whole number of samples): the line between their
  // filled neighbours, with an error kEmptyBinErrorFactor times the largest other bin's
  std::size_t empty = 0;
  std::vector<double> y;    // mean per bin
  std::vector<double> se;   // its standard error
};
constexpr double kEmptyBinErrorFactor = 1e3;
FoldedPulse fold_pulse(const std::vector<double> &x, double rate, double f,
                       int oversample = kTemplateOversample, FoldPeriod how = FoldPeriod::grid);

// The bins of a fold's errors (a bank's template, written from a fold) that no pass fell in:
// those fold_pulse gave one error, kEmptyBinErrorFactor times the largest other bin's. A filled
// fold's errors vary from bin to bin; none stands alone so far above the rest.
std::size_t bins_without_passes(const std::vector<double> &se);

// Simulated folds at known sizes (deg) and angles from the load direction (deg; one angle, 0,
// when the scene has no load zone to place the pit in). Sizes x angles must form a full grid.
struct PulseTemplate {
  double size_deg = 0, angle_deg = 0;
  std::vector<double> y, se;  // as FoldedPulse, the entry at a quarter of the bins
};
struct TemplateBank {
  std::vector<PulseTemplate> templates;
  double bin_s = 0;         // as the record's fold must have
  double model_error = 0;   // relative error of the fitted size on held-out simulated sizes
  // A bank with several angles: the fitted angle's error (deg) on simulated pits between its
  // angles; NaN where the bank does not state it (then the fit's angle picks no branch).
  double angle_error_deg = std::numeric_limits<double>::quiet_NaN();
  // false: the bank's interval was never measured to cover (a bank made without held-out runs)
  bool coverage_measured = true;
  // what the bank's own held-out runs showed (ohmdem-post model); empty: a committed bank, whose
  // coverage its report measured
  std::string coverage_note;
};

struct TemplateFit {
  bool valid = false;
  std::string note;  // how, or why not determined
  double size_deg = std::numeric_limits<double>::quiet_NaN();
  double size_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double size_hi_deg = std::numeric_limits<double>::quiet_NaN();  // NaN: open above
  double angle_deg = std::numeric_limits<double>::quiet_NaN();    // banks with several angles
  double angle_lo_deg = std::numeric_limits<double>::quiet_NaN();
  double angle_hi_deg = std::numeric_limits<double>::quiet_NaN();
  // the bank's angle error (deg) in the interval above; NaN: not stated (no branch is picked)
  double angle_error_deg = std::numeric_limits<double>::quiet_NaN();
  double chi2_reduced = std::numeric_limits<double>::quiet_NaN();  // at the best fit
  double shift_s = 0;           // record minus template, at the best fit
  std::size_t passes = 0;
  std::vector<double> profile_size_deg, profile_chi2;  // the size's profile (min over angle)
};

// The bank's sizes and angles (sorted, distinct); throws std::invalid_argument when they do not
// form a full grid or a template is empty.
void bank_grid(const TemplateBank &b, std::vector<double> &sizes, std::vector<double> &angles);

// Fits the bank to the fold; `confidence` the two-sided level of the interval.
TemplateFit fit_templates(const FoldedPulse &rec, const TemplateBank &bank,
                          double confidence = 0.95);

struct Diagnosis;
struct DiagnoseOptions;
struct Signal;
struct DefectLocation;
// The record's fold at the race defect's frequency (found, or o.assume_defect's), for a bank.
FoldedPulse record_fold(const Signal &s, const Diagnosis &found, const DiagnoseOptions &o);
// diagnose's size by the template fit (o.template_bank); the position as the area method gives
// it (the inner pit's angle from the load zone's passes, the outer pit's from the phase).
DefectLocation locate_by_template(const Signal &s, const Diagnosis &found,
                                 const DiagnoseOptions &o);

}  // namespace ohmdem::post

#endif
