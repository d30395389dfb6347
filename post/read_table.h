// Reader for whitespace-separated column files: our signal.txt, LIGGGHTS `fix ave/time` and
// `fix print` files, and plain one- or many-column signals without a header.
#ifndef OHMDEM_POST_READ_TABLE_H
#define OHMDEM_POST_READ_TABLE_H

#include <string>

#include "column_table.h"

namespace ohmdem::post {

// Lines starting with '#' are comments; the last comment line right before the first data row
// names the columns when it has as many words as the rows have values. Every data row must have
// the same number of values, all numbers (NaN/Inf are kept and reported when a column is used).
// CSV (commas on the first non-comment line): a header row of names if any cell is not a
// number; text cells are allowed and make their column non-numeric (reported when used).
ColumnTable read_table(const std::string &path);

}  // namespace ohmdem::post

#endif
