// Line-by-line reading of a text file with line numbers; lines are returned without '\r'.
#ifndef OHMDEM_POST_LINE_READER_H
#define OHMDEM_POST_LINE_READER_H

#include <cstddef>
#include <fstream>
#include <string>

namespace ohmdem::post {

class LineReader {
 public:
  explicit LineReader(const std::string &path);  // throws Error if the file cannot be opened
  bool next(std::string &line);                  // false at end of file
  std::size_t line_number() const { return line_; }
  const std::string &path() const { return path_; }
  std::string where() const { return path_ + ":" + std::to_string(line_); }

 private:
  std::string path_;
  std::ifstream in_;
  std::size_t line_ = 0;
};

}  // namespace ohmdem::post

#endif
