// SPDX-License-Identifier: GPL-2.0-or-later
// Row selection in a table read by read_table (e.g. the CSV written by `collect`): filtering by
// column values (`load=fixed`) and the rows where a column holds a value.
#ifndef OHMDEM_POST_TABLE_SELECT_H
#define OHMDEM_POST_TABLE_SELECT_H

#include <cstddef>
#include <string>
#include <vector>

#include "core/column_table.h"

namespace ohmdem::post {

// Rows satisfying every condition of "COL=VALUE[,COL!=VALUE...]" (comma-separated, all must
// hold): a text cell compares as text, a number numerically (to 1e-12 relative, so "1.5"
// matches 1.50000000000), an empty cell equals nothing. An empty `where` selects every row.
// Throws Error for an unknown column or a condition without '='; an empty result is returned
// as such (the caller says what it needed).
std::vector<std::size_t> select_rows(const ColumnTable &t, const std::string &where);

// The rows of `rows` where `column` holds a finite number. Rows with an empty cell or NaN are
// left out (counted in *undefined); text or an infinite value is an Error naming the line.
std::vector<std::size_t> defined_rows(const ColumnTable &t, std::size_t column,
                                      const std::vector<std::size_t> &rows,
                                      std::size_t *undefined = nullptr);

}  // namespace ohmdem::post

#endif
