// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/line_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"
#include "core/text_scan.h"

namespace ohmdem::post {

namespace {
constexpr std::size_t kChunk = 64 * 1024;
}

LineReader::LineReader(const std::string &path, std::size_t max_line)
    : path_(path), name_(path == "-" ? "standard input" : path), max_line_(max_line)
{
  if (max_line_ < 1) throw Error("internal: line limit must be >= 1");
  struct stat st {};
  if (path == "-") {
    fd_ = 0;
  } else {
    if (::stat(path.c_str(), &st) != 0)
      throw Error("cannot open '" + path + "': " + std::strerror(errno));
    if (S_ISDIR(st.st_mode)) throw Error("'" + path + "' is a directory, expected a file");
    do {
      fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    } while (fd_ < 0 && errno == EINTR);
    if (fd_ < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
    own_fd_ = true;
  }
  if (::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode))
    size_hint_ = static_cast<std::size_t>(st.st_size);
  buf_.resize(kChunk);
}

LineReader::~LineReader()
{
  if (own_fd_) ::close(fd_);
}

// Reads the next chunk into buf_ (after the unread bytes, which are moved to the front).
bool LineReader::fill()
{
  if (eof_) return false;
  if (pos_ > 0) {
    std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
    end_ -= pos_;
    pos_ = 0;
  }
  for (;;) {
    const ssize_t n = ::read(fd_, buf_.data() + end_, buf_.size() - end_);
    if (n > 0) {
      end_ += static_cast<std::size_t>(n);
      return true;
    }
    if (n == 0) {
      eof_ = true;
      return false;
    }
    if (errno != EINTR) throw Error("read error in '" + name_ + "': " + std::strerror(errno));
  }
}

bool LineReader::read_raw(std::string &line)
{
  line.clear();
  if (!started_) {  // byte order marks: UTF-8 is skipped, UTF-16 is refused
    started_ = true;
    while (end_ - pos_ < 3 && fill()) {
    }
    const auto *b = reinterpret_cast<const unsigned char *>(buf_.data() + pos_);
    const std::size_t have = end_ - pos_;
    if (have >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF) {
      pos_ += 3;
      consumed_ += 3;
    } else if (have >= 2 && ((b[0] == 0xFF && b[1] == 0xFE) || (b[0] == 0xFE && b[1] == 0xFF))) {
      throw Error(name_ + ":1: UTF-16 text; expected ASCII or UTF-8 (save the file as UTF-8)");
    }
  }
  bool any = false, had_newline = false;
  for (;;) {
    if (pos_ == end_ && !fill()) break;
    any = true;
    const char *start = buf_.data() + pos_;
    const std::size_t avail = end_ - pos_;
    const auto *nl = static_cast<const char *>(std::memchr(start, '\n', avail));
    const std::size_t take = nl ? static_cast<std::size_t>(nl - start) : avail;
    if (std::memchr(start, '\0', take))
      throw Error(name_ + ":" + std::to_string(raw_line_ + 1) +
                  ": binary data (NUL byte); expected a text file");
    if (line.size() + take > max_line_)
      throw Error(name_ + ":" + std::to_string(raw_line_ + 1) + ": line longer than " +
                  std::to_string(max_line_) +
                  " bytes (no line break?); expected a text file with one row per line");
    line.append(start, take);
    pos_ += take + (nl ? 1 : 0);
    consumed_ += take + (nl ? 1 : 0);
    if (nl) {
      had_newline = true;
      break;
    }
  }
  if (!any) return false;
  unterminated_ = !had_newline;
  ++raw_line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

const std::string &LineReader::peek_first_content()
{
  static const std::string none;
  if (!peek_done_) {
    if (line_ != 0) throw Error("internal: peek after reading '" + name_ + "'");
    peek_done_ = true;
    std::string l;
    while (read_raw(l)) {
      if (!trim(l).empty()) {
        peeked_ = std::move(l);
        has_peeked_ = true;
        break;
      }
      ++replay_blank_;
    }
  }
  return has_peeked_ ? peeked_ : none;
}

bool LineReader::next(std::string &line)
{
  if (replay_blank_ > 0) {
    --replay_blank_;
    line.clear();
  } else if (has_peeked_) {
    has_peeked_ = false;
    line = std::move(peeked_);
  } else if (!read_raw(line)) {
    return false;
  }
  ++line_;
  return true;
}

}  // namespace ohmdem::post
