// SPDX-License-Identifier: GPL-2.0-or-later
#include "writers/signal_table.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "writers/npy_header.h"

namespace ohmdem {

namespace {

// The longest shortest-round-trip double ("-2.2250738585072014e-308") is 24 characters.
constexpr std::size_t kMaxNumber = 32;

[[noreturn]] void fail(const std::string &path, const std::string &what)
{
  throw std::runtime_error("signal table '" + path + "': " + what);
}

// write(2) until done or an error (a full disk, a file size limit): the bytes written.
std::size_t write_all(std::FILE *fp, const char *data, std::size_t n, int &err)
{
  std::size_t done = 0;
  err = 0;
  while (done < n) {
    const ssize_t k = ::write(::fileno(fp), data + done, n - done);
    if (k > 0) {
      done += static_cast<std::size_t>(k);
    } else if (k < 0 && errno == EINTR) {
      continue;
    } else {
      err = k < 0 ? errno : ENOSPC;
      break;
    }
  }
  return done;
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

std::size_t truncate_npy_table(const std::string &path, const std::vector<std::string> &columns,
                               double t, std::uint64_t &kept)
{
  const NpyHeader want = npy_table_header(columns, 0);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be read to continue it");
  std::string have(want.bytes.size(), '\0');
  const std::uint64_t size = std::filesystem::file_size(path);
  if (size < have.size() || !in.read(have.data(), static_cast<std::streamsize>(have.size())))
    fail(path, "is shorter than the .npy header of this table: continue into a new file");
  std::string same = have;
  same.replace(want.rows_offset, want.rows_width, npy_rows_field(0));
  if (same != want.bytes) {
    const auto open = have.find('{'), close = have.find('}');
    const std::string dict = open == std::string::npos || close == std::string::npos
                                 ? "not an .npy header of this kind"
                                 : have.substr(open, close - open + 1);
    fail(path, "its .npy header '" + dict + "' is not this table's (" +
                   std::to_string(columns.size()) +
                   " float64 columns with the names given): continue into a new file, or name "
                   "the same columns");
  }
  const std::size_t row_bytes = columns.size() * sizeof(double);
  const std::uint64_t whole = (size - have.size()) / row_bytes;
  const bool cut_row = (size - have.size()) % row_bytes != 0;  // a crash cut the last row
  // Read the first value of each row in blocks; the rows before the first at or after t stay.
  std::vector<double> block(4096 * columns.size());
  std::uint64_t keep = 0;
  bool cut = false;
  while (!cut && keep < whole) {
    const std::uint64_t n = std::min<std::uint64_t>(4096, whole - keep);
    if (!in.read(reinterpret_cast<char *>(block.data()),
                 static_cast<std::streamsize>(n * row_bytes)))
      fail(path, "could not be read past row " + std::to_string(keep));
    for (std::uint64_t r = 0; r < n; ++r, ++keep)
      if (block[r * columns.size()] >= t) {
        cut = true;
        break;
      }
  }
  in.close();
  const std::uint64_t keep_bytes = have.size() + keep * row_bytes;
  if (keep_bytes < size) std::filesystem::resize_file(path, keep_bytes);
  kept = keep;
  return static_cast<std::size_t>(whole - keep + (cut_row ? 1 : 0));
}

SignalTable::SignalTable(const Options &opt)
    : format_(opt.format), columns_(opt.columns), flush_seconds_(opt.flush_seconds), path_(opt.path)
{
  if (columns_.empty()) fail(path_, "no columns");
  if (format_ == Format::Npy)
    open_npy(opt);
  else
    open_text(opt);
  buffer_.resize(std::max(opt.buffer_bytes, columns_.size() * (kMaxNumber + 1) * 4));
  last_flush_ = std::chrono::steady_clock::now();
}

void SignalTable::open_text(const Options &opt)
{
  bool write_header = true;
  if (opt.append && std::filesystem::exists(path_) && std::filesystem::file_size(path_) > 0) {
    dropped_ = truncate_signal_table(path_, columns_, opt.resume_from);
    write_header = false;
  }
  fp_ = std::fopen(path_.c_str(), opt.append ? "ab" : "wb");
  if (!fp_) fail(path_, std::string("cannot be opened for writing: ") + std::strerror(errno));
  // The rows go out through write(2) in whole blocks (this class buffers): no stdio buffer.
  std::setvbuf(fp_, nullptr, _IONBF, 0);
  std::fseek(fp_, 0, SEEK_END);
  end_ = static_cast<std::uint64_t>(std::ftell(fp_));
  if (write_header) {
    const std::string h = signal_table_header(columns_) + "\n";
    int err = 0;
    if (write_all(fp_, h.data(), h.size(), err) != h.size())
      fail(path_, std::string("write failed: ") + std::strerror(err));
    end_ += h.size();
  }
}

void SignalTable::open_npy(const Options &opt)
{
  NpyHeader h;
  try {
    h = npy_table_header(columns_, 0);
  } catch (const std::invalid_argument &e) {
    fail(path_, e.what());
  }
  npy_rows_offset_ = h.rows_offset;
  if (opt.append && std::filesystem::exists(path_) && std::filesystem::file_size(path_) > 0) {
    dropped_ = truncate_npy_table(path_, columns_, opt.resume_from, npy_rows_);
    fp_ = std::fopen(path_.c_str(), "r+b");  // "a" would send the row count to the end too
    if (!fp_) fail(path_, std::string("cannot be opened for writing: ") + std::strerror(errno));
    std::setvbuf(fp_, nullptr, _IONBF, 0);
    write_npy_rows_field();
    end_ = static_cast<std::uint64_t>(std::ftell(fp_));
    return;
  }
  fp_ = std::fopen(path_.c_str(), "w+b");
  if (!fp_) fail(path_, std::string("cannot be opened for writing: ") + std::strerror(errno));
  std::setvbuf(fp_, nullptr, _IONBF, 0);
  int err = 0;
  if (write_all(fp_, h.bytes.data(), h.bytes.size(), err) != h.bytes.size())
    fail(path_, std::string("write failed: ") + std::strerror(err));
  end_ = h.bytes.size();
}

// The header's row count, rewritten in place; the file position goes back to the end.
void SignalTable::write_npy_rows_field()
{
  const std::string field = npy_rows_field(npy_rows_);
  if (std::fseek(fp_, static_cast<long>(npy_rows_offset_), SEEK_SET) != 0 ||
      std::fwrite(field.data(), 1, field.size(), fp_) != field.size() ||
      std::fseek(fp_, 0, SEEK_END) != 0)
    fail(path_, std::string("could not update the .npy row count: ") + std::strerror(errno));
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
  if (format_ == Format::Npy) {
    std::memcpy(p, values, n * sizeof(double));
    p += n * sizeof(double);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      if (i) *p++ = ' ';
      p = std::to_chars(p, p + kMaxNumber, values[i]).ptr;
    }
    *p++ = '\n';
  }
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
  if (failed_) return;  // reported once; the file ends at its last whole row
  int err = 0;
  const std::size_t done = used_ ? write_all(fp_, buffer_.data(), used_, err) : 0;
  if (done != used_) {
    // A full disk (or a size limit) took part of the block: cut the file back to its last
    // whole row, so that a reader sees only whole rows, then report.
    failed_ = true;
    const std::size_t row_bytes = columns_.size() * sizeof(double);
    std::size_t whole = 0;
    if (format_ == Format::Npy) {
      whole = done - done % row_bytes;
    } else {
      const void *nl = done ? memrchr(buffer_.data(), '\n', done) : nullptr;
      whole = nl ? static_cast<std::size_t>(static_cast<const char *>(nl) - buffer_.data()) + 1 : 0;
    }
    const bool cut = ::ftruncate(::fileno(fp_), static_cast<off_t>(end_ + whole)) == 0;
    if (format_ == Format::Npy) {
      npy_rows_ += whole / row_bytes;
      try {
        write_npy_rows_field();  // in place: needs no new space
      } catch (const std::runtime_error &) {
      }
    }
    used_ = 0;
    fail(path_, std::string("write failed (") + std::strerror(err) + "): " +
                    (cut ? "the file ends at its last whole row"
                         : "its last row may be cut (" + std::string(std::strerror(errno)) + ")"));
  }
  end_ += used_;
  if (format_ == Format::Npy && used_) {
    npy_rows_ += used_ / (columns_.size() * sizeof(double));
    write_npy_rows_field();
  }
  used_ = 0;
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace ohmdem
