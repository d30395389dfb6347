// SPDX-License-Identifier: GPL-2.0-or-later
// fix bearing/race: the keywords of model 3d (doc/fix_bearing_race.md, "Model 3d"), parsed
// into RaceSettings::model3d by parse_race_settings().
#ifndef OHMDEM_STYLE_RACE_SETTINGS_3D_H
#define OHMDEM_STYLE_RACE_SETTINGS_3D_H

#include <string>

#include "BEARING/race_settings.h"

namespace ohmdem {

class StyleArgs;

// The 3D keywords, for the list of known keywords.
const char *race_keywords_3d();
// Reads keyword `kw` and its values if it is one of model 3d's; false otherwise.
bool parse_race_keyword_3d(StyleArgs &a, const std::string &kw, RaceSettings &s);
// After all keywords: what model 3d needs and allows (errors through `a`).
void check_race_3d(StyleArgs &a, RaceSettings &s);

}  // namespace ohmdem

#endif
