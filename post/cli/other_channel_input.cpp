// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli/other_channel_input.h"

#include "cli/common.h"

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

namespace {

// A channel recorded with the record: the record's input options and time window, another
// file or column; refused unless it holds the record's rate and samples, and not the same ones.
Signal companion(const Args &a, const RunMetadata &meta, const Signal &s, const InputOptions &io,
                 const std::string &what, const std::string &name_it)
{
  InputOptions in = io;
  in.min_samples = 256;
  if (!a.has("--from") && !a.has("--keep-sliding") && meta.t_sliding_end)
    in.from = *meta.t_sliding_end;
  return load_companion(in, meta, s, {"diagnose", what, "record", name_it});
}

}  // namespace

std::optional<Signal> other_channel_input(const Args &a, const RunMetadata &meta, const Signal &s)
{
  if (!a.has("--other-channel") && !a.has("--other-file")) return std::nullopt;
  InputOptions io = input_options(a);
  if (a.has("--other-file")) io.files = {a.get("--other-file")};
  if (a.has("--other-channel")) io.column = a.get("--other-channel");
  const std::string what =
      a.has("--other-file") ? "--other-file " + io.files[0] : "--other-channel " + io.column;
  return companion(a, meta, s, io, what, "name the other bearing's sensor");
}

void add_across_options(Args &a)
{
  a.option("--across-column", "NAME",
           "the accelerometer's second axis in the record's file (column or MAT variable), at "
           "right angles to the record's in the bearing's plane (the record's axis turned +90 "
           "deg): with the record's axis along the load direction (radial load), the accelerometer "
           "size methods (double-impulse, accel-curve) give an outer defect's angle from it");
}

std::optional<Signal> across_input(const Args &a, const RunMetadata &meta, const Signal &s)
{
  if (!a.has("--across-column")) return std::nullopt;
  InputOptions io = input_options(a);
  io.column = a.get("--across-column");
  return companion(a, meta, s, io, "--across-column " + io.column, "name the sensor's second axis");
}

}  // namespace ohmdem::post::cli
