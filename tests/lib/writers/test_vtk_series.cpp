// SPDX-License-Identifier: GPL-2.0-or-later
// The file-series helpers (src_fix/lib/writers/vtk_series.*) and the bearing geometry writer
// (scene_vtk.*): names, the .pvd index, and the drawn dimensions read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "temp_dir.h"
#include "writers/scene_vtk.h"
#include "writers/vtk_series.h"

using namespace ohmdem;

TEST(VtkSeries, Names)
{
  EXPECT_EQ(expand_step("out/net.*.vtk", 1200), "out/net.1200.vtk");
  EXPECT_EQ(expand_step("a*b*", 7), "a7b7");
  EXPECT_EQ(expand_step("plain.cir", 7), "plain.cir");
  EXPECT_TRUE(has_step_wildcard("x.*.vtk"));
  EXPECT_FALSE(has_step_wildcard("x.vtk"));
  EXPECT_EQ(pvd_path("out/vtk/network.*.vtk"), "out/vtk/network.pvd");
  EXPECT_EQ(pvd_path("out/net_*.vtk"), "out/net.pvd");
  EXPECT_EQ(pvd_path("out/*.vtk"), "out/network.pvd");
  EXPECT_EQ(companion_path("out/network.*.vtk", "bearing", 300), "out/network_bearing.300.vtk");
  EXPECT_EQ(companion_path("out/network.vtk", "particles", 300), "out/network_particles.vtk");
}

namespace {
std::string file_text(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST(VtkSeries, PvdIndex)
{
  const std::string path = ohmdem::test::temp_path("series.pvd");
  PvdIndex pvd(path);
  pvd.add(0, 0.0, {ohmdem::test::temp_path("n.0.vtk"), "g.0.vtk"});
  pvd.add(100, 1e-3, {ohmdem::test::temp_path("n.100.vtk"), "g.0.vtk"});
  pvd.add(100, 1e-3, {ohmdem::test::temp_path("n.100.vtk"), "g.100.vtk"});  // replaced
  const std::string text = file_text(path);
  EXPECT_NE(text.find("<DataSet timestep=\"0\" part=\"0\" file=\"n.0.vtk\"/>"), std::string::npos);
  EXPECT_NE(text.find("<DataSet timestep=\"0.001\" part=\"1\" file=\"g.100.vtk\"/>"),
            std::string::npos);
  EXPECT_EQ(text.find("timestep=\"0.001\" part=\"1\" file=\"g.0.vtk\""), std::string::npos);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
  {
    // A run continued from step 100 in a new process (read_restart): the steps before it
    // stay indexed, step 100 is rewritten, nothing later survives.
    PvdIndex more(path);
    more.add(100, 1e-3, {ohmdem::test::temp_path("n.100.vtk"), "g.100.vtk"});
    more.add(200, 2e-3, {ohmdem::test::temp_path("n.200.vtk")});
    const std::string t = file_text(path);
    EXPECT_NE(t.find("<DataSet timestep=\"0\" part=\"1\" file=\"g.0.vtk\"/>"), std::string::npos);
    EXPECT_NE(t.find("<DataSet timestep=\"0.002\" part=\"0\" file=\"n.200.vtk\"/>"),
              std::string::npos);
    std::size_t count = 0;
    for (auto at = t.find("<DataSet"); at != std::string::npos; at = t.find("<DataSet", at + 1))
      ++count;
    EXPECT_EQ(count, 5u);  // 0: two parts, 100: two parts, 200: one
    // A new run from step 0 in the same place starts the collection afresh.
    PvdIndex fresh(path);
    fresh.add(0, 0.0, {"n.0.vtk"});
    EXPECT_EQ(file_text(path).find("n.100.vtk"), std::string::npos);
  }
  std::remove(path.c_str());
  PvdIndex bad("/nonexistent-dir/x.pvd");
  EXPECT_THROW(bad.add(0, 0.0, {"a.vtk"}), std::runtime_error);
}

// SKF 6208 (doc/bearing_catalog.md): Dext 73.2 mm, Dinn 48 mm, grooves 6.65 / 6.55 mm; the
// drawn groove bottoms and the cage must have exactly those radii.
TEST(SceneVtk, BearingDimensions)
{
  RingShape inner, outer;
  inner.radius = 0.024;
  inner.groove = 0.00655;
  outer.radius = 0.0366;
  outer.groove = 0.00665;
  outer.inner = false;
  outer.centre[0] = 1e-6;  // a ring centre off the axis: radii measured from it
  CageShape cage;
  cage.radius = 0.0303;
  cage.height = 0.0063;
  std::stringstream os;
  write_bearing_vtk(os, {inner, outer}, &cage, 60, 4);
  std::string word;
  std::size_t npts = 0;
  while (os >> word && word != "POINTS") {
  }
  os >> npts >> word;
  std::vector<std::array<double, 3>> p(npts);
  for (auto &q : p) os >> q[0] >> q[1] >> q[2];
  // Points are written body by body: inner (60 x 5), outer (60 x 5), cage (60 x 2).
  ASSERT_EQ(npts, 60u * 5 * 2 + 60u * 2);
  double inner_min = 1, outer_max = 0;
  for (std::size_t k = 0; k < 300; ++k)
    inner_min = std::min(inner_min, std::hypot(p[k][0], p[k][1]));
  for (std::size_t k = 300; k < 600; ++k)
    outer_max = std::max(outer_max, std::hypot(p[k][0] - 1e-6, p[k][1]));
  EXPECT_NEAR(inner_min, 0.024, 1e-15);
  EXPECT_NEAR(outer_max, 0.0366, 1e-15);
  for (std::size_t k = 600; k < npts; ++k) EXPECT_NEAR(std::hypot(p[k][0], p[k][1]), 0.0303, 1e-15);
}
