// SPDX-License-Identifier: GPL-2.0-or-later
// Reader for LIGGGHTS/LAMMPS log files: the thermo blocks of every run (a block starts at a
// header line whose first word is `Step` and ends at `Loop time of`), and the `timestep`
// commands echoed in the log.
#ifndef OHMDEM_POST_READ_LOG_H
#define OHMDEM_POST_READ_LOG_H

#include <string>
#include <vector>

#include "core/column_table.h"
#include "io/line_reader.h"

namespace ohmdem::post {

struct LogBlock {
  ColumnTable table;        // names from the header line (Step, Atoms, KinEng, c_x, ...)
  double timestep = 0;      // last `timestep` command before the block, 0 if none seen
  std::size_t skipped = 0;  // non-thermo lines inside the block (INFO/WARNING messages)
};

// Throws Error if the file holds no thermo block with at least one row.
std::vector<LogBlock> read_log(const std::string &path);
std::vector<LogBlock> read_log(LineReader &in);  // from an open input

// The last `timestep` command echoed in a log (s); Error if there is none.
double log_timestep(const std::string &path);

// True if the first non-blank line announces a LIGGGHTS/LAMMPS log.
bool looks_like_log(const std::string &first_line);

}  // namespace ohmdem::post

#endif
