// SPDX-License-Identifier: GPL-2.0-or-later
// The forms of a deck's variables (variable_forms.h).
#include "writers/variable_forms.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace ohmdem {

namespace {

std::vector<std::string> alternatives(const std::string &form)
{
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t bar = form.find('|', start);
    out.push_back(form.substr(start, bar == std::string::npos ? bar : bar - start));
    if (bar == std::string::npos) break;
    start = bar + 1;
  }
  return out;
}

bool is_number(const std::string &v)
{
  if (v.empty() || v.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
  char *end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  return end == v.c_str() + v.size() && std::isfinite(x);
}

// No blank or control character (a LIGGGHTS command splits at blanks), no quote to start with
// (a word that starts with one is read up to its closing quote), none of `more`.
bool plain(const std::string &v, const char *more)
{
  if (v.empty() || v[0] == '"' || v[0] == '\'') return false;
  for (char c : v)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f || c == ' ') return false;
  return v.find_first_of(more) == std::string::npos;
}

bool is_literal(const std::string &a)
{
  return !a.empty() && plain(a, "|");
}

std::string describe(const std::string &a)
{
  if (a == "number") return "a number";
  if (a == "v_equal") return "v_NAME of an equal-style variable";
  if (a == "path") return "a path without blanks or control characters";
  if (a == "folder") return "a folder without blanks, control characters, '*' or '%'";
  if (a == "word") return "a word without blanks or control characters";
  return a;
}

}  // namespace

bool valid_form(const std::string &form)
{
  for (const auto &a : alternatives(form))
    if (!is_literal(a)) return false;
  return true;
}

std::string form_mismatch(const std::string &form, const std::string &value,
                          const std::function<VariableKind(const std::string &)> &kind)
{
  if (!valid_form(form)) throw std::invalid_argument("not a form: '" + form + "'");
  std::string expected, note;
  const auto alts = alternatives(form);
  for (std::size_t i = 0; i < alts.size(); ++i) {
    const std::string &a = alts[i];
    if (a == "number" && is_number(value)) return "";
    if (a == "path" && plain(value, "")) return "";
    if (a == "folder" && plain(value, "*%")) return "";
    if (a == "word" && plain(value, "")) return "";
    if (a == "v_equal" && value.size() > 2 && value.compare(0, 2, "v_") == 0) {
      const VariableKind k = kind(value.substr(2));
      if (k == VariableKind::Equal) return "";
      note = k == VariableKind::None ? " (no variable '" + value.substr(2) + "')"
                                     : " ('" + value.substr(2) + "' is not equal-style)";
    }
    if (a != "number" && a != "path" && a != "folder" && a != "word" && a != "v_equal" &&
        value == a)
      return "";
    expected += (i == 0 ? "" : i + 1 == alts.size() ? " or " : ", ") + describe(a);
  }
  return "expected " + expected + ", got '" + value + "'" + note;
}

}  // namespace ohmdem
