// SPDX-License-Identifier: GPL-2.0-or-later
#include "core/column_table.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

#include "core/error.h"
#include "core/text_scan.h"

namespace ohmdem::post {

namespace {
bool iequal(const std::string &a, const std::string &b)
{
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}
}  // namespace

std::size_t ColumnTable::find_name(const std::string &name) const
{
  for (std::size_t c = 0; c < names.size(); ++c)
    if (names[c] == name) return c;
  for (std::size_t c = 0; c < names.size(); ++c)
    if (iequal(names[c], name)) return c;
  return npos;
}

std::size_t ColumnTable::find(const std::string &key) const
{
  std::size_t c = find_name(key);
  if (c != npos) return c;
  if (!key.empty() && std::all_of(key.begin(), key.end(), [](char ch) {
        return std::isdigit(static_cast<unsigned char>(ch));
      })) {
    // all digits: only a number too large for long long fails
    long long k = 0;
    if (std::from_chars(key.data(), key.data() + key.size(), k).ec != std::errc())
      throw SettingError("option {input.column} expects an integer, got '" + key + "'");
    if (k >= 1 && static_cast<std::size_t>(k) <= names.size())
      return static_cast<std::size_t>(k - 1);
    throw Error(source + ": column number " + key + " out of range 1.." +
                std::to_string(names.size()));
  }
  throw Error(source + ": unknown column '" + key + "' (columns: " + column_list() + ")");
}

std::string ColumnTable::column_list() const
{
  std::string s;
  for (std::size_t c = 0; c < names.size(); ++c) {
    if (c) s += ' ';
    s += names[c];
  }
  return s;
}

void ColumnTable::init_columns(std::size_t n)
{
  columns.assign(n, {});
  stored.assign(n, true);
  first_text.assign(n, "");
  first_text_line.assign(n, 0);
  text.assign(n, {});
  digits.assign(n, 0);
  max_abs.assign(n, 0.0);
}

void ColumnTable::note_token(std::size_t column, std::string_view token, double value)
{
  if (!std::isfinite(value)) return;
  digits[column] = std::max(digits[column], significant_digits(token));
  max_abs[column] = std::max(max_abs[column], std::fabs(value));
}

double ColumnTable::resolution(std::size_t column) const
{
  // a value printed with fewer digits had its trailing zeros dropped: assume at least the 6
  // significant digits of printf's %g
  return print_resolution(max_abs.at(column), std::max(digits.at(column), 6));
}

const std::vector<double> &ColumnTable::column(std::size_t c) const
{
  if (c >= stored.size() || !stored[c])
    throw Error("internal: column " + std::to_string(c + 1) + " of " + source + " not stored");
  return columns[c];
}

void ColumnTable::require_finite(std::size_t column) const
{
  const auto &v = this->column(column);
  if (column < first_text.size() && !first_text[column].empty())
    throw Error(source + ":" + std::to_string(first_text_line[column]) + ": column " +
                names[column] + " is not numeric ('" + first_text[column] + "')");
  for (std::size_t r = 0; r < v.size(); ++r)
    if (!std::isfinite(v[r]))
      throw Error(source + ":" + std::to_string(line_of_row[r]) + ": non-finite value (" +
                  (std::isnan(v[r]) ? std::string("NaN") : std::string("Inf")) + ") in column " +
                  names[column]);
}

}  // namespace ohmdem::post
