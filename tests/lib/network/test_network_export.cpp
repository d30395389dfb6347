// SPDX-License-Identifier: GPL-2.0-or-later
// SPICE netlist and legacy-VTK writers: format, lossless numbers, order independence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "network/conduction_network.h"
#include "network/network_export.h"

using namespace ohmdem;

namespace {

std::vector<std::string> lines(const std::string &s)
{
  std::vector<std::string> out;
  std::istringstream is(s);
  for (std::string l; std::getline(is, l);) out.push_back(l);
  return out;
}

// H = 100, L = 200; a bridge through nodes 5 and 6, and a floating edge 7-8.
ConductionNetwork small_network()
{
  ConductionNetwork net;
  net.set_electrodes(100, 200);
  net.add_conductance(100, 5, 0.3);
  net.add_conductance(100, 6, 1.0 / 3.0);
  net.add_conductance(5, 200, 7.0);
  net.add_conductance(6, 200, 2.0);
  net.add_conductance(5, 6, 0.1);
  net.add_conductance(8, 7, 1.0);
  return net;
}

}  // namespace

TEST(Export, SpiceNetlistConvention)
{
  ConductionNetwork net = small_network();
  std::ostringstream os;
  write_spice_netlist(os, net, 0.1);
  const std::vector<std::string> l = lines(os.str());
  ASSERT_GE(l.size(), 10u);
  EXPECT_EQ(l[0], "ohmdem conduction network");  // title line
  EXPECT_EQ(l[l.size() - 3], "I1 0 ehigh DC 0.10000000000000001");
  EXPECT_EQ(l[l.size() - 2], ".op");
  EXPECT_EQ(l[l.size() - 1], ".end");
  // Canonical order (a < b, then g): (5,6) (5,100) (5,200) (6,100) (6,200) (7,8).
  std::vector<std::string> r;
  for (const std::string &x : l)
    if (x.rfind("R", 0) == 0 || x.rfind("* floating: R", 0) == 0) r.push_back(x);
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(r[0], "R1 n5 n6 10");
  EXPECT_EQ(r[1], "R2 n5 ehigh 3.3333333333333335");
  EXPECT_EQ(r[2], "R3 n5 0 0.14285714285714285");
  EXPECT_EQ(r[3], "R4 n6 ehigh 3");
  EXPECT_EQ(r[4], "R5 n6 0 0.5");
  EXPECT_EQ(r[5], "* floating: R6 n7 n8 1");
  // 17 significant digits: the text gives back 1/g exactly.
  EXPECT_EQ(std::strtod("3.3333333333333335", nullptr), 1.0 / 0.3);
  EXPECT_EQ(spice_node_name(net, 200), "0");
  EXPECT_EQ(spice_node_name(net, 100), "ehigh");
  EXPECT_EQ(spice_node_name(net, 42), "n42");
}

TEST(Export, SpiceNeedsElectrodes)
{
  ConductionNetwork net;
  net.add_conductance(1, 2, 1);
  std::ostringstream os;
  EXPECT_THROW(write_spice_netlist(os, net, 0.1), std::invalid_argument);
}

TEST(Export, VtkFromNodePositions)
{
  ConductionNetwork net = small_network();
  net.solve(1.0);
  std::ostringstream os;
  VtkOptions opt;
  opt.edge_scalar_names = {"area", "mask state"};
  write_vtk_network(
      os, net,
      [](NodeKey k, std::array<double, 3> &p) {
        p = {double(k), 0.5 * double(k), 0.0};
        return k != 8;  // node 8 cannot be placed: edge 7-8 is skipped
      },
      opt,
      [](const NetworkEdge &e, std::vector<double> &s) {
        s = {1e-8 * double(e.a), 1.0};
      });
  const std::vector<std::string> l = lines(os.str());
  auto find = [&](const std::string &head) {
    return std::find_if(l.begin(), l.end(),
                        [&](const std::string &x) { return x.rfind(head, 0) == 0; });
  };
  EXPECT_EQ(l[0], "# vtk DataFile Version 3.0");
  EXPECT_EQ(l[2], "ASCII");
  EXPECT_EQ(l[3], "DATASET POLYDATA");
  EXPECT_EQ(l[4], "POINTS 4 double");  // 5, 6, 100, 200
  EXPECT_EQ(*find("LINES"), "LINES 5 15");
  EXPECT_EQ(*find("POINT_DATA"), "POINT_DATA 4");
  EXPECT_EQ(*find("CELL_DATA"), "CELL_DATA 5");
  EXPECT_NE(find("SCALARS potential double 1"), l.end());
  EXPECT_NE(find("SCALARS conductance double 1"), l.end());
  EXPECT_NE(find("SCALARS current double 1"), l.end());
  EXPECT_NE(find("SCALARS area double 1"), l.end());
  EXPECT_NE(find("SCALARS mask_state double 1"), l.end());  // blanks are not allowed
  // First cell is edge (5, 6); its current is 0.1 * (V5 - V6).
  auto cur = find("SCALARS current double 1") + 2;
  EXPECT_DOUBLE_EQ(std::strtod(cur->c_str(), nullptr), 0.1 * (net.potential(5) - net.potential(6)));
  // High electrode potential = R * I.
  auto pot = find("SCALARS potential double 1") + 2;
  EXPECT_DOUBLE_EQ(std::strtod((pot + 2)->c_str(), nullptr), net.last_solution().resistance);
}

TEST(Export, VtkExplicitEdgesAreOrderIndependent)
{
  // The bearing: every ball joins the two electrode nodes; each is drawn between its own
  // contact points, so the electrode node appears once per distinct position.
  ConductionNetwork net;
  net.set_electrodes(1, 2);
  std::vector<VtkEdge> edges;
  for (int k = 0; k < 5; ++k) {
    net.add_conductance(1, 2, 0.1 * (k + 1));
    edges.push_back({1, 2, 0.1 * (k + 1), {double(k), 1, 0}, {double(k), 0, 0}, {double(k)}});
  }
  net.solve(0.5);
  VtkOptions opt;
  opt.edge_scalar_names = {"ball"};
  std::ostringstream a, b;
  write_vtk_network(a, net, edges, opt);
  std::reverse(edges.begin(), edges.end());
  write_vtk_network(b, net, edges, opt);
  EXPECT_EQ(a.str(), b.str());
  const std::vector<std::string> l = lines(a.str());
  EXPECT_EQ(l[4], "POINTS 10 double");
  // Ball k carries I * g_k / sum(g): 0.5 * 0.1 / 1.5 for the first one.
  const auto c = std::find(l.begin(), l.end(), "SCALARS current double 1") + 2;
  EXPECT_NEAR(std::strtod(c->c_str(), nullptr), 0.5 * 0.1 / 1.5, 1e-15);
  edges[0].scalars.clear();
  std::ostringstream bad;
  EXPECT_THROW(write_vtk_network(bad, net, edges, opt), std::invalid_argument);
}
