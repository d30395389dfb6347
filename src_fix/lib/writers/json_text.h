// SPDX-License-Identifier: GPL-2.0-or-later
// The one JSON writer of the engine's files (run.json): every string quoted and escaped
// (RFC 8259), every number in a form JSON reads, every key once. A value that cannot be
// written as what it claims to be is refused with a message naming its key, never written
// as it is: a path holding `"` or `","omega_inner":5000,"` stays one string value.
// Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_JSON_TEXT_H
#define OHMDEM_JSON_TEXT_H

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ohmdem::json {

struct JsonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// `s` as a JSON string, quotes included: `"` and `\` escaped, control characters as \n, \t,
// ... or \u00XX, DEL as \u007f; multi-byte UTF-8 kept. Throws JsonError when `s` is not valid
// UTF-8 (JSON text is Unicode: a byte that is no character cannot be written faithfully).
std::string quote(std::string_view s);

// The number written in `text` as a JSON number: the text itself when it is one (so that a
// value keeps the digits it was given), else the shortest form that reads back to the same
// double (".5" -> 0.5, "+2" -> 2, "1." -> 1). Throws JsonError when `text` is not a finite
// number as a whole (inf, nan, "12abc", "" or blanks).
std::string number(std::string_view text);

// A flat object written in the order of its keys: {"k": v, "k2": v2}.
class Object {
 public:
  // Throws JsonError naming the key when it is given twice, or the value is refused.
  void add_string(const std::string &key, std::string_view value);
  void add_number(const std::string &key, std::string_view value);
  // A string member placed before the member `before` (at the end when there is none).
  void insert_string(const std::string &before, const std::string &key, std::string_view value);
  std::string text() const;  // the object, no line break
  const std::vector<std::pair<std::string, std::string>> &members() const { return members_; }

 private:
  void add(const std::string &key, std::string value);
  std::vector<std::pair<std::string, std::string>> members_;  // key, value as JSON text
};

// A flat object read back: its keys in order with their values as JSON text (strings with
// their quotes). Only what Object writes: strings, numbers, true/false/null. Throws JsonError
// on anything else or a key given twice.
std::vector<std::pair<std::string, std::string>> read_flat(std::string_view text);

// The characters of a JSON string value (its quotes removed, escapes decoded); a number or
// another value is returned as it is written.
std::string unquote(std::string_view value);

}  // namespace ohmdem::json

#endif
