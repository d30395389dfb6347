// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/text_scan.h"

#include <charconv>
#include <cmath>
#include <system_error>

#include "core/error.h"

namespace ohmdem::post {

namespace {
bool is_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f';
}
}  // namespace

void split_blanks(std::string_view line, std::vector<std::string_view> &out)
{
  out.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n) {
    while (i < n && is_blank(line[i])) ++i;
    if (i == n) break;
    std::size_t j = i;
    while (j < n && !is_blank(line[j])) ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
}

std::vector<std::string_view> split_blanks(std::string_view line)
{
  std::vector<std::string_view> out;
  split_blanks(line, out);
  return out;
}

std::vector<std::string> split_commas(const std::string &s)
{
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    std::size_t end = s.find(',', start);
    if (end == std::string::npos) end = s.size();
    if (end > start) out.push_back(s.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::string_view trim(std::string_view s)
{
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view s, std::string_view prefix)
{
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

bool parse_double(std::string_view token, double &value)
{
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char *first = token.data();
  const char *last = first + token.size();
  auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    // from_chars reports overflow/underflow without a value: map to inf / 0 explicitly.
    value =
        (token.find_first_of("eE") != std::string_view::npos &&
         token.find("e-") == std::string_view::npos && token.find("E-") == std::string_view::npos)
            ? HUGE_VAL
            : 0.0;
    if (token.front() == '-') value = -value;
    return true;
  }
  return ec == std::errc() && ptr == last;
}

int significant_digits(std::string_view token)
{
  int n = 0;
  bool leading = true;
  for (char c : token) {
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++n;
  }
  return n;
}

double print_resolution(double max_abs, int digits)
{
  if (!(max_abs > 0) || digits < 1) return 0;
  return std::pow(10.0, std::floor(std::log10(max_abs)) - digits + 1);
}

double parse_option_double(const std::string &option, const std::string &text)
{
  double v = 0;
  if (!parse_double(text, v) || !std::isfinite(v))
    throw Error("option " + option + " expects a finite number, got '" + text + "'");
  return v;
}

long long parse_option_int(const std::string &option, const std::string &text)
{
  long long v = 0;
  std::string_view t = text;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || ptr != t.data() + t.size())
    throw Error("option " + option + " expects an integer, got '" + text + "'");
  return v;
}

}  // namespace ohmdem::post
