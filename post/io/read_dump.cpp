// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/read_dump.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/column_table.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "io/line_reader.h"

namespace ohmdem::post {

Aggregate parse_aggregate(const std::string &name)
{
  if (name == "sum") return Aggregate::Sum;
  if (name == "mean") return Aggregate::Mean;
  if (name == "min") return Aggregate::Min;
  if (name == "max") return Aggregate::Max;
  if (name == "rms") return Aggregate::Rms;
  if (name == "count") return Aggregate::Count;
  throw SettingError("option {input.aggregate} expects sum|mean|min|max|rms|count, got '" + name +
                     "'");
}

const char *aggregate_name(Aggregate a)
{
  switch (a) {
    case Aggregate::Sum:
      return "sum";
    case Aggregate::Mean:
      return "mean";
    case Aggregate::Min:
      return "min";
    case Aggregate::Max:
      return "max";
    case Aggregate::Rms:
      return "rms";
    case Aggregate::Count:
      return "count";
  }
  return "?";
}

bool looks_like_dump(const std::string &first_line)
{
  return starts_with(trim(first_line), "ITEM:");
}

namespace {

struct Accumulator {
  Aggregate kind;
  double sum = 0, sum2 = 0;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  std::size_t n = 0;
  bool nan = false;
  void add(double v)
  {
    nan = nan || std::isnan(v);
    sum += v;
    sum2 += v * v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    ++n;
  }
  double value(const std::string &where, long long step) const
  {
    if (n == 0 && kind != Aggregate::Sum && kind != Aggregate::Count)
      throw SettingError(where + ": frame of step " + std::to_string(step) +
                         " has no rows to aggregate with '" + aggregate_name(kind) +
                         "'; use {input.aggregate} sum or count");
    if (nan && kind != Aggregate::Count) return std::numeric_limits<double>::quiet_NaN();
    switch (kind) {
      case Aggregate::Sum:
        return sum;
      case Aggregate::Mean:
        return sum / static_cast<double>(n);
      case Aggregate::Min:
        return lo;
      case Aggregate::Max:
        return hi;
      case Aggregate::Rms:
        return std::sqrt(sum2 / static_cast<double>(n));
      case Aggregate::Count:
        return static_cast<double>(n);
    }
    return 0;
  }
};

class DumpFile {
 public:
  DumpFile(LineReader &in, DumpSeries &out, const std::string &column, Aggregate agg)
      : in_(in), out_(out), column_(column), agg_(agg)
  {
  }

  void read()
  {
    bool any = false;
    while (in_.next(line_)) {
      std::string_view s = trim(line_);
      if (s.empty()) continue;
      if (!starts_with(s, "ITEM: TIMESTEP"))
        throw Error(in_.where() + ": expected 'ITEM: TIMESTEP', got '" +
                    std::string(s.substr(0, 40)) + "' (not a LIGGGHTS text dump?)");
      frame();
      any = true;
    }
    if (!any) throw Error(in_.name() + ": empty dump file");
  }

 private:
  std::string need_line(const char *what)
  {
    if (!in_.next(line_))
      throw Error(in_.name() + ": file ends inside a frame, expected " + what +
                  " (truncated dump?)");
    return line_;
  }

  long long need_int(const char *what)
  {
    std::string l = need_line(what);
    split_blanks(l, tok_);
    double v = 0;
    if (tok_.size() != 1 || !parse_double(tok_[0], v) || !std::isfinite(v) || v < 0 ||
        v != std::floor(v) || v > 9.0e15)
      throw Error(in_.where() + ": expected " + what + " (a non-negative integer), got '" + l +
                  "'");
    return static_cast<long long>(v);
  }

  void frame()
  {
    const long long step = need_int("the time step");
    long long rows = -1;
    for (;;) {
      std::string l = need_line("an ITEM: line");
      std::string_view s = trim(l);
      if (starts_with(s, "ITEM: NUMBER OF")) {
        rows = need_int("the number of rows");
      } else if (starts_with(s, "ITEM: BOX BOUNDS")) {
        for (int k = 0; k < 3; ++k) need_line("a box bounds line");
      } else if (starts_with(s, "ITEM: ATOMS") || starts_with(s, "ITEM: ENTRIES")) {
        if (rows < 0)
          throw Error(in_.where() + ": column header before 'ITEM: NUMBER OF ATOMS|ENTRIES'");
        header(s.substr(starts_with(s, "ITEM: ATOMS") ? 11 : 13));
        body(step, static_cast<std::size_t>(rows));
        return;
      } else if (starts_with(s, "ITEM:")) {
        // other items (e.g. ITEM: TIME in newer LAMMPS) carry one value line
        need_line("the value of an ITEM");
      } else {
        throw Error(in_.where() + ": expected an 'ITEM:' line, got '" +
                    std::string(s.substr(0, 40)) + "'");
      }
    }
  }

  void header(std::string_view names)
  {
    ColumnTable h;
    h.source = in_.name();
    for (auto w : split_blanks(names)) h.names.emplace_back(w);
    if (h.names.empty()) throw Error(in_.where() + ": dump header names no columns");
    if (out_.columns.empty()) out_.columns = h.names;
    if (column_.empty())
      throw SettingError(
          in_.name() +
          ": choose a dump column with {input.column} NAME|N (columns: " + h.column_list() + ")");
    col_ = h.find(column_);
    ncol_ = h.names.size();
    if (out_.column.empty()) out_.column = h.names[col_];
  }

  void body(long long step, std::size_t rows)
  {
    Accumulator acc{agg_};
    for (std::size_t r = 0; r < rows; ++r) {
      std::string l = need_line("a data row");
      split_blanks(l, tok_);
      if (tok_.size() != ncol_)
        throw Error(in_.where() + ": " + std::to_string(tok_.size()) + " values, expected " +
                    std::to_string(ncol_) + " (garbage or truncated row?)");
      double v = 0;
      if (!parse_double(tok_[col_], v))
        throw Error(in_.where() + ": '" + std::string(tok_[col_]) + "' is not a number");
      acc.add(v);  // a non-finite value makes the frame's value non-finite
    }
    out_.steps.push_back(static_cast<double>(step));
    out_.values.push_back(acc.value(in_.name(), step));
    ++out_.frames;
  }

  LineReader &in_;
  DumpSeries &out_;
  std::string column_;
  Aggregate agg_;
  std::string line_;
  std::vector<std::string_view> tok_;
  std::size_t col_ = 0, ncol_ = 0;
};

}  // namespace

DumpSeries read_dump(const std::vector<std::string> &paths, const std::string &column,
                     Aggregate aggregate, LineReader *first)
{
  DumpSeries out;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (i == 0 && first) {
      DumpFile(*first, out, column, aggregate).read();
    } else {
      LineReader in(paths[i]);
      DumpFile(in, out, column, aggregate).read();
    }
  }
  // sort by step (stable: the first occurrence of a step wins), drop duplicates
  std::vector<std::size_t> order(out.steps.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return out.steps[a] < out.steps[b]; });
  DumpSeries sorted = out;
  sorted.steps.clear();
  sorted.values.clear();
  for (std::size_t i : order) {
    if (!sorted.steps.empty() && out.steps[i] == sorted.steps.back()) {
      ++sorted.duplicates;
      continue;
    }
    sorted.steps.push_back(out.steps[i]);
    sorted.values.push_back(out.values[i]);
  }
  return sorted;
}

}  // namespace ohmdem::post
