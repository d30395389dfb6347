// SPDX-License-Identifier: GPL-2.0-or-later
// A table of numeric columns read from a text file, with enough provenance (source line of each
// row, printed resolution of each column, first non-finite entry) for precise error messages.
#ifndef OHMDEM_POST_COLUMN_TABLE_H
#define OHMDEM_POST_COLUMN_TABLE_H

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/row_lines.h"

namespace ohmdem::post {

struct ColumnTable {
  std::string source;              // file name, for messages
  std::vector<std::string> names;  // from the header, or "1", "2", ... without one
  bool has_header = false;
  std::vector<std::vector<double>> columns;  // columns[c][row]; empty if !stored[c]
  std::vector<bool> stored;                  // false: the reader was asked not to keep it
  std::vector<int> digits;                   // most significant digits printed, per column
  std::vector<double> max_abs;               // largest finite magnitude, per column
  RowLines line_of_row;                      // 1-based source line of each row
  std::vector<std::string> notes;            // comment lines and reader remarks
  // CSV files may hold text cells (stored as NaN): the first one of each column, and its line
  std::vector<std::string> first_text;
  std::vector<std::size_t> first_text_line;
  // CSV: per column, empty while the column has only numbers; else one entry per row, the cell
  // as written (unquoted) for a text cell, "" for a number or an empty cell
  std::vector<std::vector<std::string>> text;

  std::size_t rows() const { return line_of_row.size(); }
  std::size_t cols() const { return names.size(); }

  // Index of a column given by name (exact, then case-insensitive) or by 1-based number.
  // Throws Error naming the available columns when nothing matches.
  std::size_t find(const std::string &name_or_number) const;
  // Like find() but returns npos instead of throwing; only exact/case-insensitive names.
  std::size_t find_name(const std::string &name) const;
  std::string column_list() const;

  // Rounding step of the printed values of a column (see print_resolution).
  double resolution(std::size_t column) const;
  // Records the printed form of a value (for resolution()).
  void note_token(std::size_t column, std::string_view token, double value);
  void init_columns(std::size_t n);

  // Throws Error with the source line if the column holds NaN or Inf (or is not stored).
  void require_finite(std::size_t column) const;
  // Throws Error (internal) if the column was not kept by the reader.
  const std::vector<double> &column(std::size_t c) const;

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

}  // namespace ohmdem::post

#endif
