// SPDX-License-Identifier: GPL-2.0-or-later
#include "run_folder_fixtures.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "temp_dir.h"

namespace ohmdem::post::test {

namespace fs = std::filesystem;

// A fresh directory for one test.
std::string fresh_dir(const std::string &name)
{
  const fs::path d = ohmdem::test::temp_dir() / "collect" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

// A run folder as our decks write it: signal.txt ("# time R n_masked", 100 kHz) and run.json.
// R is a level with a pulse while n_masked > 0 (every `period` samples, `width` long) and a
// deterministic ripple; `nan_row` >= 0 puts a NaN there.
void make_run(const std::string &dir, const std::string &json, int n, int period, int width,
              double level, int nan_row)
{
  fs::create_directories(dir);
  std::ofstream s(dir + "/signal.txt");
  s << "# time R n_masked\n";
  char buf[128];
  for (int i = 0; i < n; ++i) {
    const int masked = i % period < width ? 1 : 0;
    const double r = level * (1 + 0.08 * masked) + 1e-3 * std::sin(0.37 * i);
    if (i == nan_row)
      std::snprintf(buf, sizeof buf, "%.9g nan %d\n", i * 1e-5, masked);
    else
      std::snprintf(buf, sizeof buf, "%.9g %.12g %d\n", i * 1e-5, r, masked);
    s << buf;
  }
  if (!json.empty()) std::ofstream(dir + "/run.json") << json << "\n";
}

// The study-like layout used by several tests: three runs with differing keys, a folder
// without run.json, a container folder.
std::string make_sweep(const std::string &name)
{
  const std::string root = fresh_dir(name);
  make_run(root + "/fixed_2",
           R"({"defect": "inner", "size_deg": 2, "load": "fixed", "t_sliding_end": 0.002,
               "F": 320, "area": "greenwood, exact", "tags": [1, 2], "note": null})",
           2000, 40, 6);
  make_run(root + "/fixed_10",
           R"({"defect": "inner", "size_deg": 10, "load": "fixed", "t_sliding_end": 0.002,
               "F": 320})",
           2000, 40, 12, 1.4);
  make_run(root + "/force_1", R"({"defect": "outer", "size_deg": 1, "load": "force",
           "depth": 1e-4, "resumed": true})",
           2000, 50, 3);
  make_run(root + "/no_metadata", "");
  fs::create_directories(root + "/figures");
  return root;
}

}  // namespace ohmdem::post::test
