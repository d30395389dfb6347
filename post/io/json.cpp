// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/error.h"

namespace ohmdem::post {

Json Json::array()
{
  Json j;
  j.type_ = Type::Array;
  return j;
}

Json Json::object()
{
  Json j;
  j.type_ = Type::Object;
  return j;
}

Json &Json::push_back(Json v)
{
  if (type_ != Type::Array) throw Error("internal: push_back on a non-array JSON value");
  items_.push_back(std::move(v));
  return items_.back();
}

std::size_t Json::size() const
{
  return type_ == Type::Array ? items_.size() : type_ == Type::Object ? members_.size() : 0;
}

Json &Json::set(const std::string &key, Json v)
{
  if (type_ != Type::Object) throw Error("internal: set on a non-object JSON value");
  for (auto &m : members_)
    if (m.first == key) {
      m.second = std::move(v);
      return m.second;
    }
  members_.emplace_back(key, std::move(v));
  return members_.back().second;
}

const Json *Json::find(const std::string &key) const
{
  for (const auto &m : members_)
    if (m.first == key) return &m.second;
  return nullptr;
}

std::string json_number(double v)
{
  if (!std::isfinite(v)) return "null";
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {

void escape(std::string &out, const std::string &s)
{
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void newline(std::string &out, int indent, int level)
{
  if (indent < 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * level), ' ');
}

class Parser {
 public:
  Parser(const std::string &text, const std::string &source) : s_(text), source_(source) {}

  Json document()
  {
    Json v = value(0);
    skip();
    if (i_ != s_.size()) fail("trailing characters after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string &what) const
  {
    std::size_t line = 1;
    for (std::size_t k = 0; k < i_ && k < s_.size(); ++k) line += s_[k] == '\n';
    throw Error(source_ + ":" + std::to_string(line) + ": invalid JSON: " + what);
  }
  void skip()
  {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r'))
      ++i_;
  }
  bool eat(char c)
  {
    skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  void expect(char c)
  {
    if (!eat(c)) fail(std::string("expected '") + c + "'");
  }
  bool word(const char *w)
  {
    std::string_view v(w);
    if (s_.compare(i_, v.size(), v) == 0) {
      i_ += v.size();
      return true;
    }
    return false;
  }

  Json value(int depth)
  {
    if (depth > 200) fail("nesting too deep");
    skip();
    if (i_ >= s_.size()) fail("unexpected end of input");
    const char c = s_[i_];
    if (c == '{') {
      ++i_;
      Json o = Json::object();
      if (eat('}')) return o;
      do {
        skip();
        if (i_ >= s_.size() || s_[i_] != '"') fail("expected a string key");
        const std::size_t key_at = i_;
        std::string k = string();
        // RFC 8259 leaves a repeated name's meaning open: a second value (an unescaped text
        // written into the file) must not silently replace the first
        if (o.find(k)) {
          i_ = key_at;
          fail("the key \"" + k + "\" appears twice in one object (which value is meant?)");
        }
        expect(':');
        o.set(k, value(depth + 1));
      } while (eat(','));
      expect('}');
      return o;
    }
    if (c == '[') {
      ++i_;
      Json a = Json::array();
      if (eat(']')) return a;
      do a.push_back(value(depth + 1));
      while (eat(','));
      expect(']');
      return a;
    }
    if (c == '"') return Json(string());
    if (word("true")) return Json(true);
    if (word("false")) return Json(false);
    if (word("null")) return Json();
    double d = 0;
    auto r = std::from_chars(s_.data() + i_, s_.data() + s_.size(), d);
    if (r.ec != std::errc() || r.ptr == s_.data() + i_) fail("unexpected character");
    i_ = static_cast<std::size_t>(r.ptr - s_.data());
    return Json(d);
  }

  std::string string()
  {
    ++i_;  // opening quote
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      char c = s_[i_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= s_.size()) break;
      char e = s_[i_++];
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
          if (i_ + 4 > s_.size()) fail("bad \\u escape");
          unsigned code = 0;
          auto r = std::from_chars(s_.data() + i_, s_.data() + i_ + 4, code, 16);
          if (r.ec != std::errc() || r.ptr != s_.data() + i_ + 4) fail("bad \\u escape");
          i_ += 4;
          if (code < 0x80) {
            out += static_cast<char>(code);
          } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
          } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
          }
          break;
        }
        default:
          out += e;
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }

  const std::string &s_;
  std::string source_;
  std::size_t i_ = 0;
};

}  // namespace

Json Json::parse(const std::string &text, const std::string &source)
{
  return Parser(text, source).document();
}

void Json::dump_to(std::string &out, int indent, int level) const
{
  switch (type_) {
    case Type::Null:
      out += "null";
      break;
    case Type::Bool:
      out += bool_ ? "true" : "false";
      break;
    case Type::Number:
      out += json_number(num_);
      break;
    case Type::String:
      escape(out, str_);
      break;
    case Type::Array: {
      out += '[';
      // arrays of scalars stay on one line
      bool flat = true;
      for (const auto &v : items_) flat = flat && v.type_ != Type::Array && v.type_ != Type::Object;
      for (std::size_t k = 0; k < items_.size(); ++k) {
        if (k) out += flat && indent >= 0 ? ", " : ",";
        if (!flat) newline(out, indent, level + 1);
        items_[k].dump_to(out, indent, level + 1);
      }
      if (!flat && !items_.empty()) newline(out, indent, level);
      out += ']';
      break;
    }
    case Type::Object: {
      out += '{';
      for (std::size_t k = 0; k < members_.size(); ++k) {
        if (k) out += ',';
        newline(out, indent, level + 1);
        escape(out, members_[k].first);
        out += indent >= 0 ? ": " : ":";
        members_[k].second.dump_to(out, indent, level + 1);
      }
      if (!members_.empty()) newline(out, indent, level);
      out += '}';
      break;
    }
  }
}

std::string Json::dump(int indent) const
{
  std::string out;
  dump_to(out, indent, 0);
  return out;
}

}  // namespace ohmdem::post
