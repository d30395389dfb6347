// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/setting_flags.h"

#include "core/error.h"

namespace ohmdem::post::cli {

const SettingFlags &setting_flags()
{
  static const SettingFlags flags = {
      {"bearing.factors", "--factors"},  // BearingGeometry::factors (bearing/bearing.h)
      // InputOptions (io/load_signal.h), its readers, RunMetadata (io/run_metadata.h)
      {"input.rate", "--rate"},
      {"input.rate_variable", "--rate-variable"},
      {"input.dt", "--dt"},
      {"input.column", "--column"},
      {"input.time_column", "--time-column"},
      {"input.format", "--input"},
      {"input.variable", "--variable"},
      {"input.aggregate", "--aggregate"},
      {"input.resample", "--resample"},
      {"metadata.path", "--metadata"},
      {"input.from", "--from"},
      {"input.to", "--to"},
      // SpectrumOptions (dsp/spectrum.h, dsp/window.h), SpectrogramOptions (dsp/spectrogram.h)
      {"spectrum.detrend", "--detrend"},
      {"spectrum.scale", "--scale"},
      {"spectrum.segment", "--segment"},
      {"spectrum.overlap", "--overlap"},
      {"spectrum.pad", "--pad"},
      {"spectrum.nfft", "--nfft"},
      {"spectrum.window", "--window"},
      {"spectrogram.fmin", "--fmin"},
      {"spectrogram.fmax", "--fmax"},
      // order tracking (dsp/order_tracking.h), detection (dsp/detect.h)
      {"orders.speed_unit", "--speed-unit"},
      {"orders.samples_per_rev", "--samples-per-rev"},
      {"detect.baseline", "--baseline"},
      {"detect.false_alarm", "--false-alarm"},
      // DiagnoseOptions (bearing/diagnose.h), BearingGeometry and the catalog (bearing/bearing.h)
      {"diagnose.harmonics", "--harmonics"},
      {"diagnose.tolerance", "--tolerance"},
      {"diagnose.speed_refine", "--speed-refine"},
      {"diagnose.baseline", "--baseline"},
      {"diagnose.other_channel", "--other-channel"},
      {"diagnose.load", "--load"},
      {"diagnose.assume_defect", "--assume-defect"},
      {"diagnose.size_curve", "--size-curve"},
      {"diagnose.curve_rel_error", "--size-model-error"},
      {"diagnose.width_curve", "--width-curve"},
      {"diagnose.width_rel_error", "--width-model-error"},
      {"diagnose.pulse_height", "--pulse-height"},
      {"diagnose.template_bank", "--template-bank"},
      {"diagnose.size_method", "--size-method"},
      {"diagnose.across", "--across-column"},
      {"diagnose.place_method", "--place-method"},
      {"diagnose.model", "--model"},
      {"geometry.nb", "--nb"},
      {"geometry.db", "--db"},
      {"geometry.dp", "--dp"},
      {"geometry.contact_angle_deg", "--beta"},
      {"catalog.dir", "--catalog"},
      {"catalog.name", "--bearing"},
      // find_run_folders (io/run_folders.h)
      {"runs.recursive", "--recursive"},
      // row selection (io/table_select.h), output form (report/report.h)
      {"select.where", "--where"},
      {"indicators.y", "--y"},
      {"report.format", "--format"},
      // AcquireSettings (dsp/acquire.h)
      {"acquire.scale", "--scale"},
      {"acquire.offset", "--offset"},
      {"acquire.rate", "--rate"},
      {"acquire.order", "--order"},
      {"acquire.lowpass", "--lowpass"},
      {"acquire.noise_rms", "--noise-rms"},
      {"acquire.noise_density", "--noise-density"},
      {"acquire.bits", "--bits"},
      {"acquire.range", "--range"},
  };
  return flags;
}

std::string flag_named(const std::string &text, const SettingFlags &overrides)
{
  return name_settings(text, [&](const std::string &key) {
    for (const SettingFlags *m : {&overrides, &setting_flags()}) {
      const auto it = m->find(key);
      if (it != m->end()) return it->second;
    }
    return setting_field(key);  // (a setting no flag sets: its own name)
  });
}

std::string user_message(const std::exception &e, const SettingFlags &overrides)
{
  if (const auto *s = dynamic_cast<const SettingError *>(&e))
    return flag_named(s->text(), overrides);
  return e.what();
}

}  // namespace ohmdem::post::cli
