// SPDX-License-Identifier: GPL-2.0-or-later
// Errors of the post-processing library: one exception type, caught by the command line,
// which prints "ERROR: <message>" on stderr and exits non-zero.
#ifndef OHMDEM_POST_ERROR_H
#define OHMDEM_POST_ERROR_H

#include <functional>
#include <stdexcept>
#include <string>

namespace ohmdem::post {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the library's warnings go (something kept that the user should know: a cut last row
// dropped). The command line prints them as "WARNING: <message>" on stderr; tests may catch them.
inline std::function<void(const std::string &)> &warning_sink()
{
  static std::function<void(const std::string &)> sink;
  return sink;
}
inline void warn(const std::string &message)
{
  if (warning_sink()) warning_sink()(message);
}

// "group.field" in lower case (a brace in a file name is left alone).
inline bool is_setting_name(const std::string &key)
{
  const std::size_t dot = key.find('.');
  if (dot == 0 || dot == std::string::npos || dot + 1 == key.size()) return false;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (i != dot && !((key[i] >= 'a' && key[i] <= 'z') || key[i] == '_')) return false;
  return true;
}

// The library names its settings (fields of its settings structs), never command-line flags:
// a text that concerns a setting writes it as "{group.field}", e.g. "{acquire.rate}" for
// AcquireSettings::rate. This gives `text` with each such name replaced by name_of(key).
inline std::string name_settings(const std::string &text,
                                 const std::function<std::string(const std::string &)> &name_of)
{
  std::string out;
  std::size_t p = 0;
  for (std::size_t open; (open = text.find('{', p)) != std::string::npos;) {
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    const std::string key = text.substr(open + 1, close - open - 1);
    out.append(text, p, open - p);
    out += is_setting_name(key) ? name_of(key) : text.substr(open, close + 1 - open);
    p = close + 1;
  }
  return out.append(text, p, std::string::npos);
}

// A setting's own name: the field ("rate" for "acquire.rate").
inline std::string setting_field(const std::string &key)
{
  return key.substr(key.find('.') + 1);
}

// An error about one or more settings, written with "{group.field}" names (above). what() names
// each by its field; the command line, which declared the flag that sets each field, names the
// flag instead (cli/setting_flags.h).
class SettingError : public Error {
 public:
  explicit SettingError(const std::string &text)
      : Error(name_settings(text, setting_field)), text_(text)
  {
  }
  const std::string &text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace ohmdem::post

#endif
