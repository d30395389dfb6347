// SPDX-License-Identifier: GPL-2.0-or-later
// Reader for whitespace-separated column files: our signal.txt, LIGGGHTS `fix ave/time` and
// `fix print` files, and plain one- or many-column signals without a header.
#ifndef OHMDEM_POST_READ_TABLE_H
#define OHMDEM_POST_READ_TABLE_H

#include <functional>
#include <string>
#include <vector>

#include "core/column_table.h"
#include "io/line_reader.h"

namespace ohmdem::post {

// Lines starting with '#' are comments; the last comment line right before the first data row
// names the columns when it has as many words as the rows have values. Every data row must have
// the same number of values, all numbers (NaN/Inf are kept and reported when a column is used).
// CSV (commas on the first non-comment line): a header row of names if any cell is not a
// number; text cells are allowed and make their column non-numeric (reported when used).
struct TableOptions {
  std::size_t max_line = LineReader::kDefaultMaxLine;  // bytes per line
  // Called once the column names are known: which columns to store (all when unset). Every
  // cell is still checked; only the values of the columns kept are held in memory.
  std::function<std::vector<bool>(const ColumnTable &)> keep;
  bool header_only = false;  // stop at the first data row (names, no values)
};
// A regular file starting with the .npy magic is read by read_npy (read_npy.h) instead.
ColumnTable read_table(const std::string &path, const TableOptions &opt = {});
// Reads from an open input (e.g. after the format was detected from its first line).
ColumnTable read_table(LineReader &in, const TableOptions &opt = {});

}  // namespace ohmdem::post

#endif
