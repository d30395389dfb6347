// SPDX-License-Identifier: GPL-2.0-or-later
// The JSON writer of the engine's files (json_text.h).
#include "writers/json_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace ohmdem::json {

namespace {

// Length of the UTF-8 sequence starting at s[i], 0 when it is not a valid one (overlong
// forms, surrogates and code points above U+10FFFF included).
std::size_t utf8_length(std::string_view s, std::size_t i)
{
  const auto byte = [&s](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  unsigned long cp = 0;
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf)
    n = 2, cp = c & 0x1f;
  else if (c >= 0xe0 && c <= 0xef)
    n = 3, cp = c & 0x0f;
  else if (c >= 0xf0 && c <= 0xf4)
    n = 4, cp = c & 0x07;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3f);
  }
  if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) || cp > 0x10ffff ||
      (cp >= 0xd800 && cp <= 0xdfff))
    return 0;
  return n;
}

// The JSON grammar of a number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
bool is_json_number(std::string_view t)
{
  std::size_t i = 0;
  const auto digits = [&t, &i]() {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - from;
  };
  if (i < t.size() && t[i] == '-') ++i;
  if (i < t.size() && t[i] == '0')
    ++i;
  else if (digits() == 0)
    return false;
  if (i < t.size() && t[i] == '.') {
    ++i;
    if (digits() == 0) return false;
  }
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == t.size();
}

void append_utf8(std::string &out, unsigned long cp)
{
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xc0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xe0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  }
}

// The reader of read_flat: one position in the text.
struct Reader {
  std::string_view t;
  std::size_t i = 0;
  [[noreturn]] void fail(const std::string &what) const
  {
    throw JsonError("not a flat JSON object: " + what + " at character " + std::to_string(i));
  }
  void blanks()
  {
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
  }
  void expect(char c)
  {
    blanks();
    if (i >= t.size() || t[i] != c) fail(std::string("expected '") + c + "'");
    ++i;
  }
  std::string string_text()
  {
    blanks();
    const std::size_t from = i;
    if (i >= t.size() || t[i] != '"') fail("expected a string");
    for (++i; i < t.size() && t[i] != '"'; ++i) {
      if (static_cast<unsigned char>(t[i]) < 0x20) fail("a control character in a string");
      if (t[i] == '\\') ++i;
    }
    if (i >= t.size()) fail("a string without its closing quote");
    ++i;
    return std::string(t.substr(from, i - from));
  }
  std::string value_text()
  {
    blanks();
    if (i < t.size() && t[i] == '"') return string_text();
    const std::size_t from = i;
    while (i < t.size() && t[i] != ',' && t[i] != '}' && t[i] != ' ' && t[i] != '\n' &&
           t[i] != '\t' && t[i] != '\r')
      ++i;
    const std::string_view v = t.substr(from, i - from);
    if (!(v == "true" || v == "false" || v == "null" || is_json_number(v)))
      fail("a value that is no string, number, true, false or null");
    return std::string(v);
  }
};

}  // namespace

std::string quote(std::string_view s)
{
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throw JsonError("byte " + std::string(hex) + " at character " + std::to_string(i + 1) +
                      " is not UTF-8 text");
    }
    if (n > 1) {
      out.append(s.substr(i, n));
    } else if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\b') {
      out += "\\b";
    } else if (c == '\f') {
      out += "\\f";
    } else if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\u%04x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
    i += n;
  }
  return out + "\"";
}

std::string number(std::string_view text)
{
  // Only what LIGGGHTS reads as a number (.5, +2, 1.), as a whole, finite.
  const bool plain = !text.empty() && text.find_first_not_of("0123456789+-.eE") == text.npos;
  const std::string copy(text);
  char *end = nullptr;
  const double x = plain ? std::strtod(copy.c_str(), &end) : 0.0;
  if (!plain || end != copy.c_str() + copy.size() || !std::isfinite(x))
    throw JsonError("'" + copy + "' is not a finite number");
  if (is_json_number(text)) return copy;  // the digits as given
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);  // the shortest round trip
  return std::string(buf, r.ptr);
}

void Object::add(const std::string &key, std::string value)
{
  for (const auto &m : members_)
    if (m.first == key) throw JsonError("key '" + key + "' given twice");
  members_.emplace_back(key, std::move(value));
}

void Object::add_string(const std::string &key, std::string_view value)
{
  try {
    add(key, quote(value));
  } catch (const JsonError &e) {
    if (std::string(e.what()).find("given twice") != std::string::npos) throw;
    throw JsonError(key + ": " + e.what());
  }
}

void Object::add_number(const std::string &key, std::string_view value)
{
  std::string text;
  try {
    text = number(value);
  } catch (const JsonError &e) {
    throw JsonError(key + ": " + e.what());
  }
  add(key, std::move(text));
}

void Object::insert_string(const std::string &before, const std::string &key,
                           std::string_view value)
{
  add_string(key, value);
  auto member = members_.back();
  members_.pop_back();
  auto at = members_.begin();
  while (at != members_.end() && at->first != before) ++at;
  members_.insert(at, std::move(member));
}

std::string Object::text() const
{
  std::string out = "{";
  for (std::size_t k = 0; k < members_.size(); ++k) {
    if (k) out += ", ";
    out += quote(members_[k].first) + ": " + members_[k].second;
  }
  return out + "}";
}

std::vector<std::pair<std::string, std::string>> read_flat(std::string_view text)
{
  Reader r{text};
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::string> seen;
  r.expect('{');
  r.blanks();
  if (r.i < text.size() && text[r.i] == '}') {
    ++r.i;
  } else {
    for (;;) {
      const std::string key = unquote(r.string_text());
      r.expect(':');
      std::string value = r.value_text();
      if (!seen.insert(key).second) r.fail("the key '" + key + "' given twice");
      out.emplace_back(key, std::move(value));
      r.blanks();
      if (r.i < text.size() && text[r.i] == ',') {
        ++r.i;
        continue;
      }
      r.expect('}');
      break;
    }
  }
  r.blanks();
  if (r.i != text.size()) r.fail("text after the object");
  return out;
}

std::string unquote(std::string_view v)
{
  if (v.size() < 2 || v.front() != '"' || v.back() != '"') return std::string(v);
  std::string out;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    if (v[i] != '\\') {
      out += v[i];
      continue;
    }
    const char e = ++i + 1 < v.size() ? v[i] : '\0';
    switch (e) {
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'u': {
        unsigned long cp = i + 4 < v.size()
                               ? std::strtoul(std::string(v.substr(i + 1, 4)).c_str(), nullptr, 16)
                               : 0;
        i += 4;
        // a surrogate pair: the second half follows as \uDC00..\uDFFF
        if (cp >= 0xd800 && cp <= 0xdbff && i + 6 < v.size() && v[i + 1] == '\\' &&
            v[i + 2] == 'u') {
          const unsigned long lo =
              std::strtoul(std::string(v.substr(i + 3, 4)).c_str(), nullptr, 16);
          cp = 0x10000 + ((cp - 0xd800) << 10) + (lo - 0xdc00);
          i += 6;
        }
        append_utf8(out, cp);
        break;
      }
      default:
        out += e;
        break;
    }
  }
  return out;
}

}  // namespace ohmdem::json
