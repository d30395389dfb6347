// SPDX-License-Identifier: GPL-2.0-or-later
// Time series of exported files; see vtk_series.h.
#include "writers/vtk_series.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace ohmdem {

namespace {

std::string folder_of(const std::string &path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Shortest decimal text that reads back to the same double.
std::string exact(double v)
{
  char buf[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

}  // namespace

std::string expand_step(const std::string &pattern, std::int64_t step)
{
  std::string out;
  for (char c : pattern)
    if (c == '*')
      out += std::to_string(step);
    else
      out += c;
  return out;
}

bool has_step_wildcard(const std::string &pattern)
{
  return pattern.find('*') != std::string::npos;
}

std::string series_base(const std::string &pattern)
{
  const std::string folder = folder_of(pattern);
  std::string name = pattern.substr(folder.size());
  const auto star = name.find('*');
  if (star != std::string::npos) {
    name = name.substr(0, star);
    while (!name.empty() && (name.back() == '.' || name.back() == '_' || name.back() == '-'))
      name.pop_back();
  } else if (name.size() > 4 && name.compare(name.size() - 4, 4, ".vtk") == 0) {
    name = name.substr(0, name.size() - 4);
  }
  return folder + (name.empty() ? "network" : name);
}

std::string pvd_path(const std::string &pattern)
{
  return series_base(pattern) + ".pvd";
}

std::string companion_path(const std::string &pattern, const std::string &what, std::int64_t step)
{
  const std::string base = series_base(pattern) + "_" + what;
  return has_step_wildcard(pattern) ? base + "." + std::to_string(step) + ".vtk" : base + ".vtk";
}

// The entries of an existing collection written before `time` (our own format: one DataSet
// line per part, parts of a step on consecutive lines).
void PvdIndex::keep_earlier(double time)
{
  std::ifstream in(path_);
  std::string line;
  auto attribute = [&](const std::string &name, std::string &value) {
    const std::string key = name + "=\"";
    const auto at = line.find(key);
    if (at == std::string::npos) return false;
    const auto end = line.find('"', at + key.size());
    if (end == std::string::npos) return false;
    value = line.substr(at + key.size(), end - at - key.size());
    return true;
  };
  while (std::getline(in, line)) {
    std::string t, part, file;
    if (line.find("<DataSet") == std::string::npos || !attribute("timestep", t) ||
        !attribute("part", part) || !attribute("file", file))
      continue;
    char *end = nullptr;
    const double when = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || !(when < time)) continue;
    if (part != "0" && !entries_.empty() && entries_.back().time == when)
      entries_.back().files.push_back(file);
    else
      entries_.push_back({-1, when, {file}});
  }
}

void PvdIndex::add(std::int64_t step, double time, const std::vector<std::string> &files)
{
  if (!started_) {
    started_ = true;
    keep_earlier(time);
  }
  const std::string folder = folder_of(path_);
  Entry e{step, time, {}};
  for (const std::string &f : files)
    e.files.push_back(
        !folder.empty() && f.compare(0, folder.size(), folder) == 0 ? f.substr(folder.size()) : f);
  if (!entries_.empty() && entries_.back().step == step)
    entries_.back() = std::move(e);
  else
    entries_.push_back(std::move(e));
  write();
}

void PvdIndex::write() const
{
  const std::string tmp = path_ + ".tmp";
  {
    std::ofstream os(tmp);
    if (!os) throw std::runtime_error("cannot open '" + tmp + "' for writing");
    os << "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
          "  <Collection>\n";
    for (const Entry &e : entries_)
      for (std::size_t part = 0; part < e.files.size(); ++part)
        os << "    <DataSet timestep=\"" << exact(e.time) << "\" part=\"" << part << "\" file=\""
           << e.files[part] << "\"/>\n";
    os << "  </Collection>\n</VTKFile>\n";
    if (!os) throw std::runtime_error("cannot write '" + tmp + "'");
  }
  // Replaced in one step: a reader never sees half an index.
  if (std::rename(tmp.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + tmp + "' to '" + path_ + "'");
}

}  // namespace ohmdem
