// SPDX-License-Identifier: GPL-2.0-or-later
// The header of a NumPy .npy file holding a table: a 1-D array of records with one
// little-endian float64 field per column ("descr": [('time', '<f8'), ('R', '<f8'), ...]), so
// that numpy.load gives named columns (a['R']). The row count is written in a fixed-width
// field, so that a writer can rewrite it in place as rows are added. Format: NPY version 1.0
// (2.0 when the header exceeds 65535 bytes), the header padded to a multiple of 64 bytes
// (doc/fix_signal_table.md, "Binary output"). Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_NPY_HEADER_H
#define OHMDEM_NPY_HEADER_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ohmdem {

struct NpyHeader {
  std::string bytes;             // the whole header, magic to the final newline: the data follow
  std::size_t rows_offset = 0;   // where the fixed-width row count starts in `bytes`
  std::size_t rows_width = 0;    // its width (right-aligned digits, blank-padded)
};

// Throws std::invalid_argument when a column name cannot be written in the header (empty, or
// holding a quote, a backslash or a control character).
NpyHeader npy_table_header(const std::vector<std::string> &columns, std::uint64_t rows);

// The fixed-width text of a row count, as it stands at NpyHeader::rows_offset.
std::string npy_rows_field(std::uint64_t rows);

}  // namespace ohmdem

#endif
