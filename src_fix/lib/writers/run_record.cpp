// SPDX-License-Identifier: GPL-2.0-or-later
// Which run a restart file belongs to (run_record.h).
#include "writers/run_record.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "writers/json_text.h"
#include "writers/run_folder.h"

namespace ohmdem {

namespace {
constexpr const char *kMagic = "ohmdem run record 1\n";

std::string run_file(const std::string &folder)
{
  return folder + "/.ohmdem.run";
}
}  // namespace

std::string encode_run_record(const RunRecord &record)
{
  return std::string(kMagic) + "run " + std::to_string(record.run) + "\n" + record.parameters;
}

bool decode_run_record(const std::string &bytes, RunRecord &record)
{
  const std::string magic = kMagic;
  if (bytes.compare(0, magic.size(), magic) != 0) return false;
  std::istringstream in(bytes.substr(magic.size()));
  std::string word;
  long run = -1;
  if (!(in >> word >> run) || word != "run" || run < 0) return false;
  const std::size_t line = bytes.find('\n', magic.size());
  record.run = run;
  record.parameters = line == std::string::npos ? "" : bytes.substr(line + 1);
  return true;
}

long folder_run_number(const std::string &folder)
{
  std::ifstream in(run_file(folder));
  std::string word;
  long run = 0;
  if (!(in >> word >> run) || word != "run" || run < 0) return 0;
  return run;
}

std::string set_folder_run_number(const std::string &folder, long run)
{
  return replace_file(run_file(folder), "run " + std::to_string(run) + "\n");
}

std::string begin_new_run(const std::string &folder, const std::vector<std::string> &files,
                          long &run, std::vector<std::string> &renamed)
{
  for (const auto &name : files) {
    const std::string from = folder + "/" + name, to = from + ".previous";
    if (std::rename(from.c_str(), to.c_str()) == 0)
      renamed.push_back(name);
    else if (errno != ENOENT)
      return "cannot rename " + from + " of the folder's previous run to " + to + ": " +
             std::strerror(errno);
  }
  run = folder_run_number(folder) + 1;
  return set_folder_run_number(folder, run);
}

bool is_run_parameter(const std::string &key)
{
  // how far the run got, and what it measured (model 3d: the mean contact angle at its end,
  // and the nominal one beside it)
  static const std::set<std::string> not_parameters = {
      "status",         "time_reached",    "error",         "tend",
      "ohmdem_version", "restart_changes", "contact_angle", "contact_angle_nominal"};
  return not_parameters.count(key) == 0;
}

std::vector<ParameterChange> changed_parameters(
    const std::string &before, const std::vector<std::pair<std::string, std::string>> &after)
{
  std::string text = before;
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const auto old = json::read_flat(text);
  std::vector<ParameterChange> changes;
  auto find = [](const std::vector<std::pair<std::string, std::string>> &members,
                 const std::string &key) -> const std::string * {
    for (const auto &m : members)
      if (m.first == key) return &m.second;
    return nullptr;
  };
  // Two texts of one number ("1e-6" and "1e-06") are the same parameter.
  auto same = [](const std::string &a, const std::string &b) {
    if (a == b) return true;
    if (a.empty() || b.empty() || a[0] == '"' || b[0] == '"') return false;
    char *ea = nullptr, *eb = nullptr;
    const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
    return *ea == '\0' && *eb == '\0' && x == y;
  };
  for (const auto &[key, value] : after) {
    if (!is_run_parameter(key)) continue;
    const std::string *was = find(old, key);
    if (!was || !same(*was, value)) changes.push_back({key, was ? *was : "", value});
  }
  for (const auto &[key, value] : old)
    if (is_run_parameter(key) && !find(after, key)) changes.push_back({key, value, ""});
  return changes;
}

}  // namespace ohmdem
