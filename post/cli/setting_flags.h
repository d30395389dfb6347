// SPDX-License-Identifier: GPL-2.0-or-later
// The flag that sets each library setting: the library names a setting "{group.field}"
// (core/error.h), the command line, which declares the flags, names the flag the user typed.
#ifndef OHMDEM_POST_CLI_SETTING_FLAGS_H
#define OHMDEM_POST_CLI_SETTING_FLAGS_H

#include <exception>
#include <map>
#include <string>

namespace ohmdem::post::cli {

// setting ("acquire.rate") -> flag ("--rate")
using SettingFlags = std::map<std::string, std::string>;

// The flags every command declares for the library's settings.
const SettingFlags &setting_flags();

// `text` with each "{group.field}" replaced by its flag: from `overrides` (a command whose flag
// for a setting differs: acquire's input rate is --input-rate), else from setting_flags().
std::string flag_named(const std::string &text, const SettingFlags &overrides = {});

// What the user reads of a library error: a SettingError with its settings named by their flags,
// any other Error as it is.
std::string user_message(const std::exception &e, const SettingFlags &overrides = {});

}  // namespace ohmdem::post::cli

#endif
