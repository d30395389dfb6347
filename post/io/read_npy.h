// SPDX-License-Identifier: GPL-2.0-or-later
// Reader for NumPy .npy files (format versions 1.0, 2.0, 3.0): the binary signal tables that
// `fix signal/table` writes (a 1-D array of records, one float64 field per column: the field
// names become the column names) and the arrays numpy.save writes (1-D: one column; 2-D: one
// column per index of the second axis, C or Fortran order). Element types: float64, float32,
// int64, int32, int16, int8, uint8..uint64, little-endian or byte order irrelevant.
#ifndef OHMDEM_POST_READ_NPY_H
#define OHMDEM_POST_READ_NPY_H

#include <string>

#include "core/column_table.h"
#include "io/read_table.h"

namespace ohmdem::post {

// True when the file starts with the .npy magic ("\x93NUMPY"); false for pipes and others.
bool has_npy_header(const std::string &path);

// Throws Error naming the file and what is wrong (another layout, a truncated file, ...).
// Rows are numbered from 1 in ColumnTable::line_of_row. A record table holding more whole
// rows than its header counts (a run stopped between writing rows and counting them) is
// read whole, with a note; numpy.load reads the counted rows only.
ColumnTable read_npy(const std::string &path, const TableOptions &opt = {});

}  // namespace ohmdem::post

#endif
