// Helpers of the post tests: reference data location and small file utilities.
#ifndef OHMDEM_TESTS_POST_TEST_UTIL_H
#define OHMDEM_TESTS_POST_TEST_UTIL_H

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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
  const std::string path = std::string(OHMDEM_POST_TEST_TMP) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace ohmdem::post::test

#endif
