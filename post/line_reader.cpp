#include "line_reader.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "error.h"

namespace ohmdem::post {

LineReader::LineReader(const std::string &path) : path_(path)
{
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw Error("cannot open '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Error("'" + path + "' is a directory, expected a file");
  in_.open(path, std::ios::binary);
  if (!in_) throw Error("cannot open '" + path + "'");
}

bool LineReader::next(std::string &line)
{
  if (!std::getline(in_, line)) {
    if (in_.bad()) throw Error("read error in '" + path_ + "'");
    return false;
  }
  ++line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  if (line.find('\0') != std::string::npos)
    throw Error(where() + ": binary data (NUL byte); expected a text file");
  return true;
}

}  // namespace ohmdem::post
