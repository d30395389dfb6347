// SPDX-License-Identifier: GPL-2.0-or-later
#include "output/signal_table.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace ohmdem {

namespace {

// The longest shortest-round-trip double ("-2.2250738585072014e-308") is 24 characters.
constexpr std::size_t kMaxNumber = 32;

[[noreturn]] void fail(const std::string &path, const std::string &what)
{
  throw std::runtime_error("signal table '" + path + "': " + what);
}

}  // namespace

std::string signal_table_header(const std::vector<std::string> &columns)
{
  std::string h = "#";
  for (const auto &c : columns) h += " " + c;
  return h;
}

std::size_t truncate_signal_table(const std::string &path, const std::vector<std::string> &columns,
                                  double t)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be read to continue it");
  std::string line;
  if (!std::getline(in, line)) return 0;  // empty: nothing to keep or check
  const std::string want = signal_table_header(columns);
  if (line != want)
    fail(path, "its header '" + line + "' is not this table's '" + want +
                   "': continue into a new file, or name the same columns");
  std::uintmax_t keep = static_cast<std::uintmax_t>(in.tellg());
  std::size_t dropped = 0;
  bool cut = false;
  std::size_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    // A last line without its newline was cut by a crash: it goes, whatever it holds.
    if (in.eof()) cut = true;
    if (!cut && (line.empty() || line[0] == '#')) {
      keep = static_cast<std::uintmax_t>(in.tellg());
      continue;
    }
    if (!cut) {
      const char *b = line.data();
      double v = 0;
      const auto r = std::from_chars(b, b + line.size(), v);
      if (r.ec != std::errc())
        fail(path, "row " + std::to_string(lineno) + " does not start with a number");
      if (v >= t) cut = true;
    }
    if (cut)
      ++dropped;
    else
      keep = static_cast<std::uintmax_t>(in.tellg());
  }
  in.close();
  if (keep < std::filesystem::file_size(path)) std::filesystem::resize_file(path, keep);
  return dropped;
}

SignalTable::SignalTable(const Options &opt)
    : columns_(opt.columns), flush_seconds_(opt.flush_seconds), path_(opt.path)
{
  if (columns_.empty()) fail(path_, "no columns");
  bool write_header = true;
  if (opt.append && std::filesystem::exists(path_) && std::filesystem::file_size(path_) > 0) {
    dropped_ = truncate_signal_table(path_, columns_, opt.resume_from);
    write_header = false;
  }
  fp_ = std::fopen(path_.c_str(), opt.append ? "ab" : "wb");
  if (!fp_) fail(path_, std::string("cannot be opened for writing: ") + std::strerror(errno));
  buffer_.resize(std::max(opt.buffer_bytes, columns_.size() * (kMaxNumber + 1) * 4));
  if (write_header) {
    const std::string h = signal_table_header(columns_) + "\n";
    std::fwrite(h.data(), 1, h.size(), fp_);
  }
  last_flush_ = std::chrono::steady_clock::now();
}

SignalTable::~SignalTable()
{
  if (!fp_) return;
  try {
    flush();
  } catch (const std::exception &) {
    // A destructor cannot report: the owner calls flush() itself where it can stop the run.
  }
  std::fclose(fp_);
}

void SignalTable::row(const double *values)
{
  const std::size_t n = columns_.size();
  if (buffer_.size() - used_ < n * (kMaxNumber + 1)) flush();
  char *p = buffer_.data() + used_;
  for (std::size_t i = 0; i < n; ++i) {
    if (i) *p++ = ' ';
    p = std::to_chars(p, p + kMaxNumber, values[i]).ptr;
  }
  *p++ = '\n';
  used_ = static_cast<std::size_t>(p - buffer_.data());
  // The clock costs tens of nanoseconds: look at it every 256 rows only.
  if (++rows_since_clock_ >= 256) {
    rows_since_clock_ = 0;
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_flush_).count() >= flush_seconds_) flush();
  }
}

void SignalTable::flush()
{
  if (used_ && std::fwrite(buffer_.data(), 1, used_, fp_) != used_)
    fail(path_, std::string("write failed: ") + std::strerror(errno));
  used_ = 0;
  std::fflush(fp_);
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace ohmdem
