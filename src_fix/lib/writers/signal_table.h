// SPDX-License-Identifier: GPL-2.0-or-later
// A table of numbers written row by row at full rate, rows gathered in a large buffer and
// written in blocks, flushed at least every `flush_seconds` of wall time so that a reader
// (tail -f, a crash) sees recent rows. Two formats: text ('#'-headed, each value in its
// shortest round-trip decimal form, std::to_chars: reads back to the same double) and NumPy
// .npy (a record per row, one float64 field per column: the bits themselves, no formatting;
// npy_header.h). Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_SIGNAL_TABLE_H
#define OHMDEM_SIGNAL_TABLE_H

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace ohmdem {

class SignalTable {
 public:
  enum class Format { Text, Npy };
  struct Options {
    std::string path;
    Format format = Format::Text;
    std::vector<std::string> columns;  // header names, one per value of a row
    // Continue an existing file: its header must name the same columns; rows whose first
    // value is >= `resume_from` (a run continued from an earlier restart) are dropped first.
    bool append = false;
    double resume_from = 0.0;
    std::size_t buffer_bytes = std::size_t(1) << 20;
    double flush_seconds = 1.0;
  };

  // Throws std::runtime_error naming the file and what is wrong.
  explicit SignalTable(const Options &opt);
  ~SignalTable();
  SignalTable(const SignalTable &) = delete;
  SignalTable &operator=(const SignalTable &) = delete;

  // One row of columns().size() values.
  void row(const double *values);
  // Writes the buffered rows. A failed write (a full disk) cuts the file back to its last
  // whole row and throws std::runtime_error naming the file; later calls do nothing.
  void flush();
  bool failed() const { return failed_; }
  const std::vector<std::string> &columns() const { return columns_; }
  std::size_t rows_dropped() const { return dropped_; }

 private:
  void open_text(const Options &opt);
  void open_npy(const Options &opt);
  void write_npy_rows_field();

  std::FILE *fp_ = nullptr;
  Format format_;
  std::vector<std::string> columns_;
  std::uint64_t npy_rows_ = 0;       // rows in the .npy file once the buffer is written
  std::size_t npy_rows_offset_ = 0;  // where the header's row count stands
  std::vector<char> buffer_;
  std::size_t used_ = 0;
  std::uint64_t end_ = 0;  // file size after the last whole row written
  bool failed_ = false;    // a write failed: the file was cut back to whole rows
  std::size_t dropped_ = 0;
  unsigned rows_since_clock_ = 0;
  double flush_seconds_;
  std::chrono::steady_clock::time_point last_flush_;
  std::string path_;
};

// The header line of a table with these columns: "# name1 name2 ...".
std::string signal_table_header(const std::vector<std::string> &columns);

// For SignalTable's append mode: checks that `path`'s header names `columns` and truncates
// the rows whose first value is >= t. Returns the number of rows removed. Throws
// std::runtime_error (another header, an unreadable row) naming the file.
std::size_t truncate_signal_table(const std::string &path, const std::vector<std::string> &columns,
                                  double t);
// The same for an .npy table written by SignalTable: checks the header, keeps the whole rows
// before the first whose first value is >= t (a row cut by a crash goes), sets the header's
// row count. Returns the number of rows removed and stores the rows kept in `kept`.
std::size_t truncate_npy_table(const std::string &path, const std::vector<std::string> &columns,
                               double t, std::uint64_t &kept);

}  // namespace ohmdem

#endif
