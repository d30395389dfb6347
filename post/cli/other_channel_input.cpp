// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/other_channel_input.h"

#include <cmath>

#include "cli/common.h"
#include "core/error.h"

namespace ohmdem::post::cli {

void add_other_channel_options(Args &a)
{
  a.option("--other-channel", "NAME",
           "the other bearing's sensor in the same file (MAT variable or column, e.g. FE_time "
           "for the drive end's DE_time): impulses coherent with it and stronger there are that "
           "bearing's, and a flagged record reads 'none' (impulses from the other channel) or "
           "'other-bearing'; a named family is never changed");
  a.option("--other-file", "FILE",
           "the other bearing's sensor in another file (the record's input options; "
           "--other-channel names its column)");
}

std::optional<Signal> other_channel_input(const Args &a, const RunMetadata &meta, const Signal &s)
{
  if (!a.has("--other-channel") && !a.has("--other-file")) return std::nullopt;
  InputOptions io = input_options(a);
  if (a.has("--other-file")) io.files = {a.get("--other-file")};
  if (a.has("--other-channel")) io.column = a.get("--other-channel");
  io.min_samples = 256;
  if (!a.has("--from") && !a.has("--keep-sliding") && meta.t_sliding_end)
    io.from = *meta.t_sliding_end;
  Signal o = load_named(io, meta);
  const std::string what =
      a.has("--other-file") ? "--other-file " + io.files[0] : "--other-channel " + io.column;
  if (std::fabs(o.rate / s.rate - 1) > 1e-9 || o.x.size() != s.x.size())
    throw Error("diagnose: " + what + " holds " + std::to_string(o.x.size()) + " samples at " +
                format_number(o.rate, 10) + " Hz, the record " + std::to_string(s.x.size()) +
                " at " + format_number(s.rate, 10) +
                " Hz: the two channels must be recorded together (same rate and samples)");
  if (o.x == s.x)
    throw Error("diagnose: " + what +
                " holds the record's own samples: name the other bearing's sensor");
  return o;
}

}  // namespace ohmdem::post::cli
