// SPDX-License-Identifier: GPL-2.0-or-later
// Streaming reader for LIGGGHTS text dumps (`dump custom` with `ITEM: ATOMS ...` and
// `dump local` with `ITEM: ENTRIES ...`): one column is aggregated over the rows of each frame,
// giving one value per time step. Several files are merged, sorted by time step, duplicates
// dropped (first occurrence kept).
#ifndef OHMDEM_POST_READ_DUMP_H
#define OHMDEM_POST_READ_DUMP_H

#include <string>
#include <vector>

#include "io/line_reader.h"

namespace ohmdem::post {

enum class Aggregate { Sum, Mean, Min, Max, Rms, Count };
Aggregate parse_aggregate(const std::string &name);  // throws Error naming the accepted values
const char *aggregate_name(Aggregate a);

struct DumpSeries {
  std::vector<double> steps;
  std::vector<double> values;
  std::string column;                // the column header as written in the dump
  std::vector<std::string> columns;  // all column headers of the first frame
  std::size_t frames = 0;            // frames read, before removing duplicates
  std::size_t duplicates = 0;
};

// `column` is a header name (id, x, c_cpl[3], ...) or a 1-based number; empty lists the
// available columns in the error. A frame holding a non-finite value gets the value NaN (Inf for
// an infinite value with sum/mean/min/max/rms), reported only if the frame is used. `first`, if
// given, is the open input of paths[0] (its format already detected).
DumpSeries read_dump(const std::vector<std::string> &paths, const std::string &column,
                     Aggregate aggregate, LineReader *first = nullptr);

bool looks_like_dump(const std::string &first_line);

}  // namespace ohmdem::post

#endif
