// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/args.h"

#include <cmath>

#include "core/error.h"
#include "core/sampled_signal.h"
#include "core/text_scan.h"

namespace ohmdem::post::cli {

Args::Args(std::string command, std::string synopsis, std::string description)
    : command_(std::move(command)),
      synopsis_(std::move(synopsis)),
      description_(std::move(description))
{
}

void Args::option(const std::string &name, const std::string &metavar, const std::string &help,
                  const std::string &def, int arity)
{
  specs_.push_back({name, metavar, help, def, arity});
}

void Args::flag(const std::string &name, const std::string &help)
{
  specs_.push_back({name, "", help, "", 0});
}

void Args::section(const std::string &title)
{
  specs_.push_back({"", "", title, "", -1});
}

const Args::Spec *Args::spec(const std::string &name) const
{
  for (const auto &s : specs_)
    if (s.arity >= 0 && s.name == name) return &s;
  return nullptr;
}

void Args::retired(const std::string &name, const std::string &instead)
{
  retired_[name] = instead;
}

bool Args::parse(const std::vector<std::string> &argv, std::ostream &out)
{
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string &a = argv[i];
    if (a == "--help" || a == "-h") {
      print_help(out);
      return false;
    }
    if (a.size() > 2 && a.compare(0, 2, "--") == 0) {
      std::string name = a, inline_value;
      const auto eq = a.find('=');
      const bool has_inline = eq != std::string::npos;
      if (has_inline) {
        name = a.substr(0, eq);
        inline_value = a.substr(eq + 1);
      }
      if (const auto r = retired_.find(name); r != retired_.end())
        throw Error(command_ + ": option " + name + " is not taken any more: " + r->second);
      const Spec *s = spec(name);
      if (!s)
        throw Error(command_ + ": unknown option '" + name + "' (see ohmdem-post " + command_ +
                    " --help)");
      auto &vals = given_[name];
      vals.clear();
      if (s->arity == 0) {
        if (has_inline) throw Error(command_ + ": option " + name + " takes no value");
        continue;
      }
      if (has_inline && s->arity == 1) {
        vals.push_back(inline_value);
        continue;
      }
      for (int k = 0; k < s->arity; ++k) {
        if (i + 1 >= argv.size())
          throw Error(command_ + ": option " + name + " expects " +
                      (s->arity == 1 ? "a value" : std::to_string(s->arity) + " values") + " (" +
                      s->metavar + ")");
        vals.push_back(argv[++i]);
      }
      continue;
    }
    positional_.push_back(a);
  }
  return true;
}

void Args::print_help(std::ostream &out) const
{
  out << "usage: ohmdem-post " << command_ << " " << synopsis_ << "\n\n" << description_ << "\n";
  for (const auto &s : specs_) {
    if (s.arity < 0) {
      out << "\n" << s.help << ":\n";
      continue;
    }
    std::string head = "  " + s.name + (s.metavar.empty() ? "" : " " + s.metavar);
    if (head.size() < 26)
      head.resize(26, ' ');
    else
      head += "\n" + std::string(26, ' ');
    out << head;
    // wrap the description at 100 columns, continuation lines indented under it
    std::string text = s.help + (s.def.empty() ? "" : " [default: " + s.def + "]");
    std::size_t col = 26;
    std::size_t pos = 0;
    while (pos < text.size()) {
      std::size_t end = text.find(' ', pos);
      if (end == std::string::npos) end = text.size();
      const std::string word = text.substr(pos, end - pos);
      if (col > 26 && col + 1 + word.size() > 100) {
        out << "\n" << std::string(26, ' ');
        col = 26;
      } else if (col > 26) {
        out << ' ';
        ++col;
      }
      out << word;
      col += word.size();
      pos = end + 1;
    }
    out << "\n";
  }
  out << "  --help                  this text\n";
}

std::vector<std::string> Args::given_values(const std::string &except) const
{
  std::vector<std::string> all;
  for (const auto &kv : given_)
    if (kv.first != except) all.insert(all.end(), kv.second.begin(), kv.second.end());
  return all;
}

bool Args::has(const std::string &name) const
{
  return given_.count(name) != 0;
}

std::string Args::get(const std::string &name) const
{
  auto it = given_.find(name);
  if (it != given_.end() && !it->second.empty()) return it->second.front();
  const Spec *s = spec(name);
  return s ? s->def : "";
}

std::vector<std::string> Args::values(const std::string &name) const
{
  auto it = given_.find(name);
  return it == given_.end() ? std::vector<std::string>{} : it->second;
}

double Args::number(const std::string &name, double fallback) const
{
  const std::string v = get(name);
  if (v.empty()) return fallback;
  return parse_option_double(name, v);
}

long long Args::integer(const std::string &name, long long fallback) const
{
  const std::string v = get(name);
  if (v.empty()) return fallback;
  return parse_option_int(name, v);
}

bool Range::contains(double v) const
{
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::text() const
{
  if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + format_number(lo);
  if (std::isinf(lo)) return (hi_open ? "< " : "<= ") + format_number(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
         (hi_open ? ")" : "]");
}

long long Args::integer_in(const std::string &name, long long fallback, long long lo, long long hi,
                           const std::string &what) const
{
  const long long v = integer(name, fallback);
  if (v < lo || v > hi)
    throw Error("option " + name + " expects " + what + " " +
                (hi == LLONG_MAX ? ">= " + std::to_string(lo)
                                 : "in " + std::to_string(lo) + ".." + std::to_string(hi)) +
                ", got " + std::to_string(v));
  return v;
}

double Args::number_in(const std::string &name, double fallback, const Range &range,
                       const std::string &what, const std::string &unit) const
{
  const double v = number(name, fallback);
  if (!range.contains(v))
    throw Error("option " + name + " expects " + what + " " + range.text() +
                (unit.empty() ? "" : " " + unit) + ", got " + format_number(v));
  return v;
}

std::string Args::choice(const std::string &name, const std::vector<std::string> &choices) const
{
  const std::string v = get(name);
  std::string list;
  for (const auto &c : choices) {
    if (v == c) return v;
    list += (list.empty() ? "" : "|") + c;
  }
  throw Error("option " + name + " expects " + list + ", got '" + v + "'");
}

}  // namespace ohmdem::post::cli
