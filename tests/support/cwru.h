// SPDX-License-Identifier: GPL-2.0-or-later
// The measured CWRU records of ../shared/data/bearing-real (beside the source tree, as in CI):
// where they are, and the rates, speeds and bearing geometry their README lists.
#ifndef OHMDEM_TESTS_SUPPORT_CWRU_H
#define OHMDEM_TESTS_SUPPORT_CWRU_H

#include <sys/stat.h>

#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace ohmdem::test {

inline std::string cwru_dir()
{
  return std::string(OHMDEM_SOURCE_DIR) + "/../shared/data/bearing-real";
}

inline bool cwru_present()
{
  struct stat st {};
  return ::stat((cwru_dir() + "/README.md").c_str(), &st) == 0;
}

struct CwruRecord {
  std::string name;
  double rate = 0, rpm = 0;
};

struct CwruReadme {
  std::vector<CwruRecord> records;
  std::string nb, db_mm, dp_mm, angle_deg;
};

inline CwruReadme parse_cwru_readme(const std::string &path)
{
  std::ifstream in(path);
  CwruReadme r;
  std::string line;
  std::smatch m;
  const std::regex row(R"(^\|\s*(sig\d+)\s*\|\s*([0-9.]+)\s*\|\s*([0-9.]+)\s*\|)");
  const std::regex balls(R"(^\|\s*number of balls\s*\|\s*([0-9]+)\s*\|)");
  const std::regex ball(R"(^\|\s*ball diameter\s*\|.*\(([0-9.]+) mm\))");
  const std::regex pitch(R"(^\|\s*pitch diameter\s*\|.*\(([0-9.]+) mm\))");
  const std::regex angle(R"(^\|\s*contact angle\s*\|\s*([0-9.]+) deg)");
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, row))
      r.records.push_back({m[1], std::stod(m[2]), std::stod(m[3])});
    if (std::regex_search(line, m, balls)) r.nb = m[1];
    if (std::regex_search(line, m, ball)) r.db_mm = m[1];
    if (std::regex_search(line, m, pitch)) r.dp_mm = m[1];
    if (std::regex_search(line, m, angle)) r.angle_deg = m[1];
  }
  return r;
}

}  // namespace ohmdem::test

#endif
