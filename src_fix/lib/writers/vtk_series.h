// SPDX-License-Identifier: GPL-2.0-or-later
// Time series of exported files, the way LAMMPS dumps and ParaView expect them, plain C++
// (no LIGGGHTS types): a `*` in a file name stands for the step; a ParaView collection
// (.pvd) indexes the files of each written step with its time; companion files (particles,
// bearing geometry) are named after the series. doc/compute_network_resistance.md.
#ifndef OHMDEM_VTK_SERIES_H
#define OHMDEM_VTK_SERIES_H

#include <cstdint>
#include <string>
#include <vector>

namespace ohmdem {

// `pattern` with every `*` replaced by the step.
std::string expand_step(const std::string &pattern, std::int64_t step);
bool has_step_wildcard(const std::string &pattern);

// Names derived from a VTK file name. A series `DIR/NAME.*.vtk` (any text around the `*`)
// has the base `DIR/NAME` (the text before the `*`, separators `.`, `_`, `-` at its end
// dropped; `DIR/network` if nothing is left); a single file `DIR/NAME.vtk` the base
// `DIR/NAME`.
std::string series_base(const std::string &pattern);
// The collection file: base + ".pvd".
std::string pvd_path(const std::string &pattern);
// A companion file of kind `what` ("particles", "bearing") at `step`: base + "_" + what +
// "." + step + ".vtk" for a series, base + "_" + what + ".vtk" for a single file.
std::string companion_path(const std::string &pattern, const std::string &what, std::int64_t step);

// A ParaView collection file (VTKFile type="Collection"), rewritten after every step added
// so that it is complete whenever a run stops: each step lists its files as parts 0, 1, ...
// (ParaView shows them together). File names are stored relative to the .pvd's folder.
// A step added again (a second run starting at the step the first ended on) replaces it.
// A collection already in the file when the first step is added (a run continued after
// read_restart, in a new process) keeps its entries of earlier times: the series goes on,
// nothing indexed before is lost; its entries at or after that time (left by a run that went
// further) are dropped, as the new run rewrites those steps.
class PvdIndex {
 public:
  explicit PvdIndex(std::string path) : path_(std::move(path)) {}
  // Throws std::runtime_error naming the file if it cannot be written.
  void add(std::int64_t step, double time, const std::vector<std::string> &files);
  const std::string &path() const { return path_; }

 private:
  struct Entry {
    std::int64_t step;
    double time;
    std::vector<std::string> files;
  };
  void write() const;
  void keep_earlier(double time);
  std::string path_;
  std::vector<Entry> entries_;
  bool started_ = false;
};

}  // namespace ohmdem

#endif
