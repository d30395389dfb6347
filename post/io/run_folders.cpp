// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/run_folders.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.h"

namespace ohmdem::post {

namespace fs = std::filesystem;

namespace {

// "runs/a/" -> "runs/a", "./runs//a" -> "runs/a", "" -> "."
std::string display_path(const fs::path &p)
{
  std::string s = p.lexically_normal().generic_string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s.empty() ? "." : s;
}

bool is_file(const fs::path &p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

}  // namespace

std::string run_signal_file(const std::string &run)
{
  const std::string text = run + "/signal.txt", binary = run + "/signal.npy";
  return !is_file(text) && is_file(binary) ? binary : text;
}

namespace {

// "" when `dir` is a run, else why not; `container` is set when it holds neither file.
std::string run_status(const fs::path &dir, bool &container)
{
  const bool sig = is_file(dir / "signal.txt") || is_file(dir / "signal.npy"),
             meta = is_file(dir / "run.json");
  container = !sig && !meta;
  if (sig && meta) return "";
  if (sig) return "no run.json";
  if (meta) return "no signal.txt";
  return "no signal.txt and no run.json";
}

struct Found {
  std::string display, identity;
};

// The case folders listed in DIR/sweep_cases.csv (first column `case`, written by the sweep
// launchers, doc/case_table.md) with their line numbers; empty when DIR is no sweep root.
// A line that names no plain folder is reported in `bad`.
std::vector<std::pair<std::string, int>> sweep_cases(
    const fs::path &dir, std::vector<std::pair<std::string, std::string>> &bad)
{
  std::vector<std::pair<std::string, int>> cases;
  const fs::path table = dir / "sweep_cases.csv";
  std::ifstream in(table);
  if (!in) return cases;
  std::string line;
  bool header = true;
  for (int n = 1; std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::string first = line.substr(0, line.find(','));
    if (header) {
      header = false;
      if (first != "case") {
        bad.emplace_back(display_path(table),
                         "line " + std::to_string(n) + ": the first column is not 'case'");
        return cases;
      }
      continue;
    }
    if (first.empty() || first == "." || first == ".." ||
        first.find_first_of("/\"") != std::string::npos)
      bad.emplace_back(display_path(table),
                       "line " + std::to_string(n) + ": '" + first + "' is not a case folder name");
    else
      cases.emplace_back(first, n);
  }
  return cases;
}

std::string identity_of(const fs::path &dir)
{
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(dir, ec);
  return ec ? display_path(fs::absolute(dir, ec)) : c.generic_string();
}

}  // namespace

bool natural_less(const std::string &a, const std::string &b)
{
  auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      std::size_t i1 = i, j1 = j;
      while (i1 < a.size() && digit(a[i1])) ++i1;
      while (j1 < b.size() && digit(b[j1])) ++j1;
      std::size_t i0 = i, j0 = j;  // skip leading zeros
      while (i0 + 1 < i1 && a[i0] == '0') ++i0;
      while (j0 + 1 < j1 && b[j0] == '0') ++j0;
      if (i1 - i0 != j1 - j0) return i1 - i0 < j1 - j0;
      const int c = a.compare(i0, i1 - i0, b, j0, j1 - j0);
      if (c != 0) return c < 0;
      i = i1;
      j = j1;
      continue;
    }
    if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
    ++i;
    ++j;
  }
  if ((a.size() - i) != (b.size() - j)) return a.size() - i < b.size() - j;
  return a < b;  // equal in natural order ("a01" vs "a1"): byte order decides
}

RunFolders find_run_folders(const std::vector<std::string> &paths, bool recursive)
{
  std::vector<Found> found;
  std::vector<std::pair<std::string, std::string>> skipped;
  for (const std::string &given : paths) {
    fs::path dir(given.empty() ? "." : given);
    const std::string shown = display_path(dir);
    std::error_code ec;
    const fs::file_status st = fs::status(dir, ec);
    if (ec || !fs::exists(st)) {
      skipped.emplace_back(shown, "does not exist");
      continue;
    }
    if (fs::is_regular_file(st)) {
      if (dir.filename() != "signal.txt" && dir.filename() != "signal.npy") {
        skipped.emplace_back(shown, "not a folder (give run folders or their signal.txt)");
        continue;
      }
      dir = dir.parent_path();
      if (dir.empty()) dir = ".";
    } else if (!fs::is_directory(st)) {
      skipped.emplace_back(shown, "not a folder");
      continue;
    }
    bool container = false;
    const std::string why = run_status(dir, container);
    if (why.empty()) found.push_back({display_path(dir), identity_of(dir)});
    if (!recursive && container && is_file(dir / "sweep_cases.csv")) {
      // A sweep root: its cases, as listed; one not run (yet) is said.
      std::vector<std::pair<std::string, std::string>> bad;
      const auto cases = sweep_cases(dir, bad);
      skipped.insert(skipped.end(), bad.begin(), bad.end());
      for (const auto &[name, line] : cases) {
        bool c = false;
        const std::string w = run_status(dir / name, c);
        const std::string shown_case = display_path(dir / name);
        if (w.empty())
          found.push_back({shown_case, identity_of(dir / name)});
        else
          skipped.emplace_back(shown_case, "case of sweep_cases.csv line " + std::to_string(line) +
                                               " not run (yet): " + w);
      }
      if (cases.empty() && bad.empty())
        skipped.emplace_back(display_path(dir), "sweep_cases.csv lists no case");
      continue;
    }
    if (!recursive) {
      if (!why.empty())
        skipped.emplace_back(display_path(dir),
                             why + (container ? "; {runs.recursive} searches its subfolders" : ""));
      continue;
    }
    std::size_t runs_below = 0;
    try {
      for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied),
           end;
           it != end; ++it) {
        const fs::directory_entry &e = *it;
        if (e.is_symlink() || !e.is_directory()) continue;
        const std::string name = e.path().filename().string();
        if (!name.empty() && name[0] == '.') {
          it.disable_recursion_pending();
          continue;
        }
        bool cont = false;
        const std::string w = run_status(e.path(), cont);
        if (w.empty()) {
          found.push_back(
              {display_path(dir / e.path().lexically_relative(dir)), identity_of(e.path())});
          ++runs_below;
        } else if (!cont) {
          skipped.emplace_back(display_path(dir / e.path().lexically_relative(dir)), w);
        }
      }
    } catch (const fs::filesystem_error &e) {
      skipped.emplace_back(display_path(dir), std::string("cannot search: ") + e.what());
    }
    if (!why.empty() && !container) skipped.emplace_back(display_path(dir), why);
    if (why.empty() || runs_below) continue;
    if (container) skipped.emplace_back(display_path(dir), "no run folder in it or below");
  }
  std::sort(found.begin(), found.end(),
            [](const Found &p, const Found &q) { return natural_less(p.display, q.display); });
  RunFolders r;
  std::set<std::string> seen;
  for (const auto &f : found)
    if (seen.insert(f.identity).second) r.runs.push_back(f.display);
  std::sort(skipped.begin(), skipped.end(), [](const auto &p, const auto &q) {
    return natural_less(p.first, q.first) || (p.first == q.first && p.second < q.second);
  });
  skipped.erase(std::unique(skipped.begin(), skipped.end()), skipped.end());
  r.skipped = std::move(skipped);
  return r;
}

RunParameters run_parameters(const std::string &path, std::vector<std::string> *nonscalar)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open metadata file '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  const Json j = Json::parse(ss.str(), path);
  if (!j.is_object()) throw Error(path + ": metadata must be a JSON object");
  std::vector<std::pair<std::string, Json>> out;
  for (const auto &m : j.members()) {
    switch (m.second.type()) {
      case Json::Type::Null:
        break;
      case Json::Type::Number:
      case Json::Type::String:
      case Json::Type::Bool:
        out.push_back(m);
        break;
      case Json::Type::Array:
      case Json::Type::Object:
        if (nonscalar) nonscalar->push_back(m.first);
        break;
    }
  }
  return out;
}

const Json *find_parameter(const RunParameters &params, const std::string &key)
{
  for (const auto &kv : params)
    if (kv.first == key) return &kv.second;
  return nullptr;
}

namespace {

bool key_less(const std::string &a, const std::string &b)
{
  std::string la = a, lb = b;
  for (char &c : la) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (char &c : lb) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return la != lb ? la < lb : a < b;
}

bool same_value(const Json *p, const Json *q)
{
  if (!p || !q) return p == q;
  if (p->type() != q->type()) return false;
  if (p->is_number()) return p->number() == q->number();
  if (p->is_string()) return p->string() == q->string();
  return p->boolean() == q->boolean();
}

}  // namespace

std::vector<std::string> parameter_keys(const std::vector<const RunParameters *> &runs,
                                        bool varying_only)
{
  std::set<std::string> all;
  for (const RunParameters *r : runs)
    for (const auto &kv : *r) all.insert(kv.first);
  std::vector<std::string> keys(all.begin(), all.end());
  std::sort(keys.begin(), keys.end(), key_less);
  if (!varying_only || runs.empty()) return keys;
  std::vector<std::string> varying;
  for (const auto &k : keys) {
    const Json *first = find_parameter(*runs.front(), k);
    for (const RunParameters *r : runs)
      if (!same_value(first, find_parameter(*r, k))) {
        varying.push_back(k);
        break;
      }
  }
  return varying;
}

}  // namespace ohmdem::post
