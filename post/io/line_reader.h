// SPDX-License-Identifier: GPL-2.0-or-later
// Line-by-line reading of a text input with line numbers: a file, or standard input for "-".
// The input is opened and read once, so pipes, FIFOs and /dev/stdin work like files: format
// detection peeks at the first non-blank line and hands it back to the parser. Lines are
// returned without '\n' and '\r'; a UTF-8 byte order mark is skipped; a line longer than the
// limit or a NUL byte is an error naming the input and the line (memory stays bounded).
#ifndef OHMDEM_POST_LINE_READER_H
#define OHMDEM_POST_LINE_READER_H

#include <cstddef>
#include <string>
#include <vector>

namespace ohmdem::post {

class LineReader {
 public:
  static constexpr std::size_t kDefaultMaxLine = std::size_t(1) << 20;  // 1 MiB

  // Throws Error if the input cannot be opened or is a directory. "-" is standard input.
  explicit LineReader(const std::string &path, std::size_t max_line = kDefaultMaxLine);
  ~LineReader();
  LineReader(const LineReader &) = delete;
  LineReader &operator=(const LineReader &) = delete;

  bool next(std::string &line);  // false at end of input

  // The first non-blank line ("" if there is none), without consuming it: next() then returns
  // the lines before it (as empty lines) and this line again, with the same line numbers.
  const std::string &peek_first_content();

  std::size_t line_number() const { return line_; }
  // The line last read ended at the end of the input without its line break (cut?).
  bool line_unterminated() const { return unterminated_; }
  const std::string &path() const { return path_; }  // as given ("-" for standard input)
  const std::string &name() const { return name_; }  // for messages: "standard input" for "-"
  std::string where() const { return name_ + ":" + std::to_string(line_); }
  // Size of a regular file (bytes), 0 for a pipe, FIFO or terminal; and the bytes consumed so
  // far: together they estimate the rows to come, so columns can reserve their final size.
  std::size_t size_hint() const { return size_hint_; }
  std::size_t bytes_consumed() const { return consumed_; }
  std::size_t max_line() const { return max_line_; }

 private:
  bool read_raw(std::string &line);
  bool fill();

  std::string path_, name_;
  int fd_ = -1;
  bool own_fd_ = false;
  std::size_t max_line_;
  std::vector<char> buf_;
  std::size_t pos_ = 0, end_ = 0;
  bool eof_ = false, started_ = false, peek_done_ = false, unterminated_ = false;
  std::size_t line_ = 0, raw_line_ = 0;
  std::size_t size_hint_ = 0, consumed_ = 0;
  // peeked lines handed back: `replay_blank_` blank lines, then `peeked_` if `has_peeked_`
  std::size_t replay_blank_ = 0;
  bool has_peeked_ = false;
  std::string peeked_;
};

}  // namespace ohmdem::post

#endif
