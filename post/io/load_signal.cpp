// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/load_signal.h"

#include <algorithm>
#include <filesystem>

#include "core/error.h"
#include "core/text_scan.h"
#include "io/line_reader.h"
#include "io/read_dump.h"
#include "io/read_log.h"
#include "io/read_mat.h"
#include "io/read_npy.h"
#include "io/read_table.h"

namespace ohmdem::post {

namespace {

// MAT files are binary: recognised by the format "mat", the .mat extension, or their header (probed
// on regular files only: a pipe cannot be read twice) before any text reader opens them.
bool is_mat_input(const InputOptions &opt)
{
  if (opt.format == "mat") return true;
  if (opt.format != "auto") return false;
  const std::string &f = opt.files.front();
  if (f == "-") return false;
  std::error_code ec;
  return has_mat_extension(f) || (std::filesystem::is_regular_file(f, ec) && has_mat_header(f));
}

// .npy files likewise: the format "npy", or their magic (the extension alone is not trusted); a
// binary table is a table (the format "table", what collect asks for, reads it too).
bool is_npy_input(const InputOptions &opt)
{
  if (opt.format == "npy") return true;
  return (opt.format == "auto" || opt.format == "table") && opt.files.front() != "-" &&
         has_npy_header(opt.files.front());
}

std::string detect(const InputOptions &opt, LineReader &in)
{
  if (opt.format != "auto") {
    if (opt.format != "table" && opt.format != "log" && opt.format != "dump" && opt.format != "mat")
      throw SettingError("option {input.format} expects auto|table|log|dump|mat|npy, got '" +
                         opt.format + "'");
    return opt.format;
  }
  const std::string &l = in.peek_first_content();
  if (l.empty()) throw Error(in.name() + ": empty file");
  if (looks_like_dump(l)) return "dump";
  if (looks_like_log(l)) return "log";
  return "table";
}

bool is_step_name(const std::string &n)
{
  return n == "TimeStep" || n == "Step" || n == "step" || n == "timestep";
}

double step_length(const InputOptions &opt, const RunMetadata &meta, double from_file,
                   const std::string &what)
{
  if (opt.dt > 0) return opt.dt;
  if (from_file > 0) return from_file;
  if (meta.dt && *meta.dt > 0) return *meta.dt;
  throw SettingError(
      what + " counts time steps and no step length is known: pass {input.dt} SECONDS" +
      std::string(meta.present() ? "" : " (or a run.json with \"dt\" via {metadata.path})"));
}

// Time-stamped samples before the window and the uniformity check.
struct Samples {
  std::vector<double> t, x;
  double t_resolution = 0;
  double rate = 0;  // > 0: uniform by declaration (InputOptions::rate), t is ignored
  RowLines lines;
  std::string where, name;
  std::string column;  // as named in the file, for messages
  MetaList meta;
};

void describe(Samples &s, const std::string &format, const std::string &time_base)
{
  s.meta.insert(s.meta.begin(), {"format", format});
  s.meta.emplace_back("time base", time_base);
}

// `read` reads the table with the options given (text or .npy).
template <class Read>
Samples from_table(const InputOptions &opt, const RunMetadata &meta, Read read)
{
  if (opt.files.size() != 1)
    throw Error("column files are read one at a time, got " + std::to_string(opt.files.size()) +
                " files");
  // the time and value columns are chosen from the names, before the rows are read: only
  // these two are kept in memory
  std::size_t tc = ColumnTable::npos, vc = ColumnTable::npos;
  TableOptions to;
  to.keep = [&](const ColumnTable &t) {
    if (opt.rate <= 0 && opt.time_column != "none") {
      if (!opt.time_column.empty()) {
        tc = t.find(opt.time_column);
      } else {
        for (const char *n : {"time", "t", "TimeStep", "Step", "step"})
          if ((tc = t.find_name(n)) != ColumnTable::npos) break;
      }
    }
    if (!opt.column.empty()) {
      vc = t.find(opt.column);
    } else {
      std::vector<std::size_t> candidates;
      for (std::size_t c = 0; c < t.cols(); ++c)
        if (c != tc) candidates.push_back(c);
      if (candidates.size() == 1) {
        vc = candidates.front();
      } else if ((vc = t.find_name("R")) == ColumnTable::npos || vc == tc) {
        throw SettingError(t.source + ": " + std::to_string(t.cols()) +
                           " columns; choose the signal with {input.column} NAME|N (columns: " +
                           t.column_list() + ")");
      }
    }
    std::vector<bool> keep(t.cols(), false);
    keep[vc] = true;
    if (tc != ColumnTable::npos) keep[tc] = true;
    return keep;
  };
  ColumnTable t = read(to);
  // a text cell makes the column unusable wherever it is; NaN/Inf only inside the window
  if (!t.first_text[vc].empty())
    throw Error(t.source + ":" + std::to_string(t.first_text_line[vc]) + ": column " + t.names[vc] +
                " is not numeric ('" + t.first_text[vc] + "')");
  // the time column must be usable throughout: it places the window
  if (opt.rate <= 0 && tc != ColumnTable::npos) t.require_finite(tc);
  Samples s;
  s.where = t.source;
  s.lines = std::move(t.line_of_row);
  s.x = tc == vc ? t.columns[vc] : std::move(t.columns[vc]);
  std::string base;
  if (opt.rate > 0) {
    s.rate = opt.rate;
    base = "uniform, {input.rate}";
  } else if (tc == ColumnTable::npos) {
    throw SettingError(
        t.source + ": no time column (columns: " + t.column_list() +
        "); pass {input.rate} HZ for a uniformly sampled signal or {input.time_column} NAME|N");
  } else {
    s.t = std::move(t.columns[tc]);
    s.t_resolution = t.resolution(tc);
    if (is_step_name(t.names[tc])) {
      const double dt = step_length(opt, meta, 0, "column " + t.names[tc]);
      for (double &v : s.t) v *= dt;
      s.t_resolution *= dt;
      base = "column " + t.names[tc] + " x dt " + format_number(dt) + " s";
    } else {
      base = "column " + t.names[tc] + " (s)";
    }
  }
  s.name = t.has_header ? t.names[vc] : t.cols() == 1 ? "x" : "column " + t.names[vc];
  s.column = t.names[vc];
  s.meta.insert(s.meta.begin(), {"column", t.names[vc]});
  describe(s, t.has_header ? "columns with header" : "plain columns", base);
  if (!t.notes.empty() && t.notes.back().rfind("read ", 0) == 0)
    s.meta.emplace_back("note", t.notes.back());
  return s;
}

Samples from_log(const InputOptions &opt, const RunMetadata &meta, LineReader &in)
{
  if (opt.files.size() != 1) throw Error("log files are read one at a time");
  const std::string path = in.name();
  auto blocks = read_log(in);
  const ColumnTable &first = blocks.front().table;
  if (opt.column.empty())
    throw SettingError(path + ": choose a thermo column with {input.column} NAME|N (columns: " +
                       first.column_list() + ")");
  const std::string name = first.names[first.find(opt.column)];
  std::vector<double> time, x;
  RowLines lines;
  double last_step = -1, dt_seen = 0, res = 0;
  bool has_time = false;
  std::size_t used = 0, skipped = 0;
  for (const auto &b : blocks) {
    const ColumnTable &t = b.table;
    const std::size_t vc = t.find_name(name), sc = t.find_name("Step");
    if (vc == ColumnTable::npos || sc == ColumnTable::npos) continue;
    const std::size_t tc = t.find_name("Time");
    if (tc == ColumnTable::npos && opt.dt <= 0 && b.timestep > 0) {
      if (dt_seen > 0 && dt_seen != b.timestep)
        throw SettingError(path + ": the timestep changes between runs (" + format_number(dt_seen) +
                           " then " + format_number(b.timestep) +
                           " s); pass {input.dt} to override");
      dt_seen = b.timestep;
    }
    ++used;
    skipped += b.skipped;
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const double step = t.columns[sc][r];
      if (step <= last_step) continue;  // a run repeats the last step of the previous one
      last_step = step;
      if (tc != ColumnTable::npos) {
        time.push_back(t.columns[tc][r]);
        res = std::max(res, t.resolution(tc));
        has_time = true;
      } else {
        time.push_back(step);
      }
      x.push_back(t.columns[vc][r]);
      lines.push_back(t.line_of_row[r]);
    }
  }
  std::string base = "thermo column Time (s)";
  if (!has_time) {
    const double dt = step_length(opt, meta, dt_seen, path + ": thermo column Step");
    for (double &v : time) v *= dt;
    base = "Step x dt " + format_number(dt) + " s" +
           (opt.dt > 0    ? " ({input.dt})"
            : dt_seen > 0 ? " (timestep in the log)"
                          : " (metadata)");
  }
  Samples s;
  s.t = std::move(time);
  s.x = std::move(x);
  s.t_resolution = res;
  s.lines = std::move(lines);
  s.where = path;
  s.name = name;
  s.column = name;
  s.meta.insert(s.meta.begin(), {"column", name});
  s.meta.emplace_back("thermo blocks used",
                      std::to_string(used) + " of " + std::to_string(blocks.size()));
  if (skipped) s.meta.emplace_back("message lines skipped", std::to_string(skipped));
  describe(s, "LIGGGHTS log", base);
  return s;
}

Samples from_mat(const InputOptions &opt)
{
  MatSignal m = read_mat_signal(opt.files, opt.column, opt.rate, opt.rate_variable);
  Samples s;
  s.x = std::move(m.x);
  s.rate = m.rate;
  s.where = opt.files.front();
  s.name = m.name;
  s.meta = std::move(m.meta);
  return s;
}

Samples from_dump(const InputOptions &opt, const RunMetadata &meta, LineReader &in)
{
  DumpSeries d = read_dump(opt.files, opt.column, opt.aggregate, &in);
  const double dt = step_length(opt, meta, 0, "a dump (dumps carry no time step length)");
  for (double &v : d.steps) v *= dt;
  Samples s;
  s.t = std::move(d.steps);
  s.x = std::move(d.values);
  s.where = opt.files.size() == 1 ? in.name() : "dump files";
  s.name = d.column;
  s.column = d.column;
  s.meta.insert(s.meta.begin(), {"column", std::string(aggregate_name(opt.aggregate)) + " of " +
                                               d.column + " per frame"});
  s.meta.emplace_back("frames", std::to_string(d.frames) + " read, " +
                                    std::to_string(d.duplicates) + " duplicate steps dropped");
  describe(s, "LIGGGHTS dump", "time step x dt " + format_number(dt) + " s");
  return s;
}

// First index in [0, n) whose time is not before (`after` false) / after (`after` true) `v`,
// times increasing: std::lower_bound / std::upper_bound without a vector of times.
template <class Time>
std::size_t first_index(std::size_t n, Time time, double v, bool after)
{
  std::size_t lo = 0, hi = n;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (after ? !(v < time(mid)) : time(mid) < v)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

template <class T>
void keep_range(std::vector<T> &v, std::size_t i0, std::size_t i1)
{
  if (v.size() < i1) return;
  v.erase(v.begin() + static_cast<long>(i1), v.end());  // in place: no second copy
  v.erase(v.begin(), v.begin() + static_cast<long>(i0));
}

}  // namespace

Signal load_signal(const InputOptions &opt, const RunMetadata &meta)
{
  if (opt.files.empty()) throw Error("no input file given");
  if (opt.rate < 0 || opt.dt < 0) throw SettingError("{input.rate} and {input.dt} must be > 0");
  if (std::count(opt.files.begin(), opt.files.end(), "-") > 1)
    throw Error("standard input ('-') can be read only once");
  Samples in;
  if (is_mat_input(opt)) {
    in = from_mat(opt);
  } else if (is_npy_input(opt)) {
    in = from_table(opt, meta,
                    [&](const TableOptions &to) { return read_npy(opt.files.front(), to); });
    in.meta.front().second = "NumPy .npy, " + in.meta.front().second;
  } else {
    LineReader first(opt.files.front());
    const std::string format = detect(opt, first);
    in = format == "dump" ? from_dump(opt, meta, first)
         : format == "log"
             ? from_log(opt, meta, first)
             : from_table(opt, meta, [&](const TableOptions &to) { return read_table(first, to); });
  }
  const std::size_t n = in.x.size();
  auto time = [&](std::size_t i) {
    return in.rate > 0 ? static_cast<double>(i) / in.rate : in.t[i];
  };
  // the window is applied to the time stamps, before the uniformity check
  const bool windowed = std::isfinite(opt.from) || std::isfinite(opt.to);
  if (std::isfinite(opt.from) && std::isfinite(opt.to) && !(opt.to > opt.from))
    throw SettingError("{input.to} (" + format_number(opt.to) + " s) must be after {input.from} (" +
                       format_number(opt.from) + " s)");
  std::size_t i0 = 0, i1 = n;
  if (std::isfinite(opt.from)) i0 = first_index(n, time, opt.from, false);
  if (std::isfinite(opt.to)) i1 = first_index(n, time, opt.to, true);
  if (i1 < i0) i1 = i0;
  const std::size_t need = std::max<std::size_t>(opt.min_samples, 2);
  if (i1 - i0 < need) {
    if (windowed && n > 0)
      throw Error("the time window [" +
                  format_number(std::isfinite(opt.from) ? opt.from : time(0)) + ", " +
                  format_number(std::isfinite(opt.to) ? opt.to : time(n - 1)) + "] s holds " +
                  std::to_string(i1 - i0) + " sample(s), at least " + std::to_string(need) +
                  " needed (the data span " + format_number(time(0)) + " to " +
                  format_number(time(n - 1)) + " s)");
    throw Error(in.where + ": only " + std::to_string(n) + " sample(s), at least " +
                std::to_string(need) + " needed");
  }
  // values outside the window are not used, so not checked
  for (std::size_t i = i0; i < i1; ++i)
    if (!std::isfinite(in.x[i]))
      throw Error((i < in.lines.size() ? in.where + ":" + std::to_string(in.lines[i])
                                       : in.where + " (sample " + std::to_string(i) + ")") +
                  ": non-finite value (" + (std::isnan(in.x[i]) ? "NaN" : "Inf") + ") in column " +
                  in.column + " at t = " + format_number(time(i)) + " s" +
                  (windowed ? " (inside the window)" : ""));
  const double t_first = time(i0);
  keep_range(in.t, i0, i1);
  keep_range(in.x, i0, i1);
  in.lines = in.lines.slice(i0, i1);
  Signal s;
  if (in.rate > 0) {
    s.rate = in.rate;
    s.t0 = t_first;
    s.x = std::move(in.x);
  } else {
    s = make_uniform(in.t, std::move(in.x), in.t_resolution, opt.resample, in.where, in.lines);
    std::vector<double>().swap(in.t);
  }
  s.name = in.name;
  std::string src;
  for (const auto &f : opt.files)
    src += (src.empty() ? "" : " ") + (f == "-" ? "standard input" : f);
  MetaList meta_out{{"source", src}};
  meta_out.insert(meta_out.end(), in.meta.begin(), in.meta.end());
  meta_out.insert(meta_out.end(), s.meta.begin(), s.meta.end());
  meta_out.emplace_back("sampling rate (Hz)", format_number(s.rate, 10));
  if (windowed)
    meta_out.emplace_back(
        "window", format_number(s.t0) + " to " + format_number(s.time(s.size() - 1)) + " s");
  meta_out.emplace_back("samples", std::to_string(s.size()));
  meta_out.emplace_back("duration (s)", format_number(s.duration()));
  meta_out.emplace_back("frequency resolution (Hz)",
                        format_number(s.rate / static_cast<double>(s.size())));
  s.meta = std::move(meta_out);
  return s;
}

}  // namespace ohmdem::post
