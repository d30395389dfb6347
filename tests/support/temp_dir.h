// SPDX-License-Identifier: GPL-2.0-or-later
// One temporary folder per test process, made on first use and removed at exit: CTest runs
// tests in parallel, so fixed names under /tmp would collide between two test processes.
#ifndef OHMDEM_TESTS_SUPPORT_TEMP_DIR_H
#define OHMDEM_TESTS_SUPPORT_TEMP_DIR_H

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

namespace ohmdem::test {

class TempDir {
 public:
  TempDir()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "ohmdem_test_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a temporary folder from " + pattern);
    path_ = pattern;
  }
  ~TempDir()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  const std::filesystem::path &path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The process's folder (made on the first call, removed at exit).
inline const std::filesystem::path &temp_dir()
{
  static const TempDir dir;
  return dir.path();
}

// A path named `name` in the process's folder (the file itself is not created).
inline std::string temp_path(const std::string &name)
{
  return (temp_dir() / name).string();
}

}  // namespace ohmdem::test

#endif
