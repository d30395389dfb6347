// SPDX-License-Identifier: GPL-2.0-or-later
// Global restart data of an ohmdem fix, the LAMMPS convention for Fix::write_restart: process
// 0 writes the size in bytes, then the values; Fix::restart(buf) gets the values back.
//
// A fix lists the members its record holds once, in a template member that takes a visitor,
// and calls it with a RestartWriter in write_restart and a RestartReader in restart: the two
// cannot disagree on the order.
#ifndef OHMDEM_SUPPORT_GLOBAL_RESTART_H
#define OHMDEM_SUPPORT_GLOBAL_RESTART_H

#include <cstddef>
#include <cstdio>
#include <vector>

namespace ohmdem {

// Collects the listed values as doubles (integers and flags exactly: they are small).
class RestartWriter {
 public:
  template <class... T> void operator()(const T &...x)
  {
    (values_.push_back(static_cast<double>(x)), ...);
  }
  void write(int me, FILE *fp) const
  {
    if (me != 0) return;
    const int size = static_cast<int>(values_.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(values_.data(), sizeof(double), values_.size(), fp);
  }

 private:
  std::vector<double> values_;
};

// Assigns the record's values to the listed members, in the order they are listed.
class RestartReader {
 public:
  explicit RestartReader(const char *buf) : values_(reinterpret_cast<const double *>(buf)) {}
  template <class... T> void operator()(T &...x) { (assign(x), ...); }
  // The value at slot i, for a check before anything is assigned.
  double at(std::size_t i) const { return values_[i]; }

 private:
  template <class T> void assign(T &x) { x = static_cast<T>(values_[next_++]); }
  void assign(bool &x) { x = values_[next_++] != 0.0; }
  const double *values_;
  std::size_t next_ = 0;
};

}  // namespace ohmdem

#endif
