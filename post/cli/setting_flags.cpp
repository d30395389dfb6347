// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/setting_flags.h"

#include "core/error.h"

namespace ohmdem::post::cli {

const SettingFlags &setting_flags()
{
  static const SettingFlags flags = {
      // InputOptions (io/load_signal.h) and the MAT reader (io/read_mat.h)
      {"input.rate", "--rate"},
      {"input.rate_variable", "--rate-variable"},
      {"input.dt", "--dt"},
      {"input.column", "--column"},
      {"input.time_column", "--time-column"},
      {"input.format", "--input"},
      {"input.from", "--from"},
      {"input.to", "--to"},
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
