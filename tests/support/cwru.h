// SPDX-License-Identifier: GPL-2.0-or-later
// The measured CWRU records of ../shared/data/bearing-real (beside the source tree, as in CI):
// where they are, and the rates, speeds and bearing geometry their README lists.
#ifndef OHMDEM_TESTS_SUPPORT_CWRU_H
#define OHMDEM_TESTS_SUPPORT_CWRU_H

#include <sys/stat.h>

#include <cctype>
#include <fstream>
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

// A README table row's cells, trimmed: "| a | b |" -> {"a", "b"}; none for a line that is not
// a row. (Plain string work: std::regex draws GCC 12's false -Wmaybe-uninitialized under ASan.)
inline std::vector<std::string> table_cells(const std::string &line)
{
  std::vector<std::string> cells;
  if (line.empty() || line[0] != '|') return cells;
  std::string::size_type at = 1;
  for (std::string::size_type bar; (bar = line.find('|', at)) != std::string::npos; at = bar + 1) {
    std::string c = line.substr(at, bar - at);
    const auto b = c.find_first_not_of(" \t"), e = c.find_last_not_of(" \t");
    cells.push_back(b == std::string::npos ? std::string() : c.substr(b, e - b + 1));
  }
  return cells;
}

// The leading run of digits (and dots, with `dots`) of text.
inline std::string leading_number(const std::string &text, bool dots)
{
  std::string::size_type n = 0;
  while (n < text.size() &&
         (std::isdigit(static_cast<unsigned char>(text[n])) || (dots && text[n] == '.')))
    ++n;
  return text.substr(0, n);
}

// The millimetres of a cell ending "... (7.940 mm)".
inline std::string millimetres(const std::string &cell)
{
  const auto open = cell.rfind('(');
  if (open == std::string::npos || cell.size() < 4 || cell.compare(cell.size() - 4, 4, " mm)") != 0)
    return "";
  const std::string number = leading_number(cell.substr(open + 1), true);
  return open + 1 + number.size() + 4 == cell.size() && !number.empty() ? number : "";
}

inline CwruReadme parse_cwru_readme(const std::string &path)
{
  std::ifstream in(path);
  CwruReadme r;
  std::string line;
  while (std::getline(in, line)) {
    const std::vector<std::string> c = table_cells(line);
    if (c.size() < 2) continue;
    const std::string &key = c[0], &value = c[1];
    const bool signal = key.size() > 3 && key.compare(0, 3, "sig") == 0 &&
                        leading_number(key.substr(3), false).size() == key.size() - 3;
    if (signal && c.size() >= 3 && !value.empty() && !c[2].empty() &&
        leading_number(value, true) == value && leading_number(c[2], true) == c[2])
      r.records.push_back({key, std::stod(value), std::stod(c[2])});
    if (key == "number of balls" && !value.empty() && leading_number(value, false) == value)
      r.nb = value;
    if (key == "ball diameter" && !millimetres(value).empty()) r.db_mm = millimetres(value);
    if (key == "pitch diameter" && !millimetres(value).empty()) r.dp_mm = millimetres(value);
    if (key == "contact angle") {
      const std::string deg = leading_number(value, true);
      if (!deg.empty() && value.compare(deg.size(), 4, " deg") == 0) r.angle_deg = deg;
    }
  }
  return r;
}

}  // namespace ohmdem::test

#endif
