// SPDX-License-Identifier: GPL-2.0-or-later
// Helpers of the post tests: reference data location and small file utilities.
#ifndef OHMDEM_TESTS_POST_TEST_UTIL_H
#define OHMDEM_TESTS_POST_TEST_UTIL_H

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "temp_dir.h"

namespace ohmdem::post::test {

inline std::string source_dir()
{
  return OHMDEM_POST_TEST_DIR;
}
inline std::string data(const std::string &name)
{
  return source_dir() + "/data/" + name;
}
inline std::string reference(const std::string &name)
{
  return source_dir() + "/reference/" + name;
}

inline std::string slurp(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Rows of whitespace-separated numbers.
inline std::vector<std::vector<double>> read_rows(const std::string &path)
{
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<double> row;
    double v;
    while (ls >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

inline std::vector<double> read_column(const std::string &path, std::size_t c = 0)
{
  std::vector<double> out;
  for (const auto &r : read_rows(path)) out.push_back(r.at(c));
  return out;
}

// Writes text to a fresh file under the test's temporary directory; returns its path.
inline std::string write_temp(const std::string &name, const std::string &text)
{
  const std::string path = ohmdem::test::temp_dir().string() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// Whether the file starts with the PNG signature.
inline bool is_png(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && std::string(sig, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}

// Whether gnuplot can render the plots (or OHMDEM_GNUPLOT names one).
inline bool have_gnuplot()
{
  return std::system("command -v gnuplot > /dev/null 2>&1") == 0 || std::getenv("OHMDEM_GNUPLOT");
}

// Expects an Error whose message contains `part`.
template <class F>
void expect_error(F f, const std::string &part)
{
  try {
    f();
    ADD_FAILURE() << "no error, expected one containing '" << part << "'";
  } catch (const Error &e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
        << "message: " << e.what() << "\nexpected to contain: " << part;
  }
}

}  // namespace ohmdem::post::test

#endif
