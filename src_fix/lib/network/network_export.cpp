// SPDX-License-Identifier: GPL-2.0-or-later
// SPICE and legacy-VTK writers; see network_export.h for the conventions.
#include "network/network_export.h"

#include "common/constants.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <stdexcept>
#include <utility>

namespace ohmdem {

namespace {

// 17 significant digits: a double survives the text round trip.
std::string num(double x)
{
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// One line only (a newline in a title would start a new SPICE/VTK statement).
std::string one_line(std::string s)
{
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\r', ' ');
  return s;
}

// VTK array names cannot contain blanks.
std::string vtk_name(std::string s)
{
  for (char &c : s)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
  return s.empty() ? std::string("unnamed") : s;
}

// Keys of the component that holds `root`, found on the edge list itself: the netlist must
// not depend on whether (or how) the network was solved.
std::vector<NodeKey> component_of(const std::vector<NetworkEdge> &edges, NodeKey root)
{
  std::vector<NodeKey> keys;
  for (const NetworkEdge &e : edges) {
    keys.push_back(e.a);
    keys.push_back(e.b);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  auto idx = [&](NodeKey k) {
    return static_cast<int>(std::lower_bound(keys.begin(), keys.end(), k) - keys.begin());
  };
  std::vector<std::vector<int>> adj(keys.size());
  for (const NetworkEdge &e : edges) {
    adj[idx(e.a)].push_back(idx(e.b));
    adj[idx(e.b)].push_back(idx(e.a));
  }
  std::vector<NodeKey> out;
  if (!std::binary_search(keys.begin(), keys.end(), root)) return out;
  std::vector<char> seen(keys.size(), 0);
  std::vector<int> queue{idx(root)};
  seen[queue[0]] = 1;
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (int j : adj[queue[q]])
      if (!seen[j]) {
        seen[j] = 1;
        queue.push_back(j);
      }
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (seen[i]) out.push_back(keys[i]);
  return out;
}

// Total order on doubles (NaN last) so that caller scalars holding NaN keep std::sort valid.
int cmp(double x, double y)
{
  const bool nx = std::isnan(x), ny = std::isnan(y);
  if (nx || ny) return int(nx) - int(ny);
  return x < y ? -1 : (y < x ? 1 : 0);
}

bool edge_less(const VtkEdge &x, const VtkEdge &y)
{
  if (x.a != y.a) return x.a < y.a;
  if (x.b != y.b) return x.b < y.b;
  std::vector<double> u{x.conductance}, v{y.conductance};
  u.insert(u.end(), x.pa.begin(), x.pa.end());
  u.insert(u.end(), x.pb.begin(), x.pb.end());
  u.insert(u.end(), x.scalars.begin(), x.scalars.end());
  v.insert(v.end(), y.pa.begin(), y.pa.end());
  v.insert(v.end(), y.pb.begin(), y.pb.end());
  v.insert(v.end(), y.scalars.begin(), y.scalars.end());
  for (std::size_t i = 0; i < u.size() && i < v.size(); ++i)
    if (const int c = cmp(u[i], v[i])) return c < 0;
  return u.size() < v.size();
}

void write_scalars(std::ostream &os, const std::string &name, const char *type,
                   const std::vector<std::string> &values)
{
  os << "SCALARS " << name << ' ' << type << " 1\nLOOKUP_TABLE default\n";
  for (const std::string &v : values) os << v << '\n';
}

}  // namespace

std::string spice_node_name(const ConductionNetwork &net, NodeKey key)
{
  if (net.has_electrodes() && key == net.low()) return "0";
  if (net.has_electrodes() && key == net.high()) return "ehigh";
  return "n" + std::to_string(key);
}

void write_spice_netlist(std::ostream &os, const ConductionNetwork &net, double current,
                         const SpiceOptions &options)
{
  if (!net.has_electrodes())
    throw std::invalid_argument("write_spice_netlist: the electrodes are not set");
  const std::vector<NetworkEdge> edges = net.edges();
  const std::vector<NodeKey> live = component_of(edges, net.high());
  auto is_live = [&](NodeKey k) { return std::binary_search(live.begin(), live.end(), k); };
  // The first line of a SPICE deck is its title, whatever it holds.
  os << one_line(options.title) << '\n';
  os << "* " << edges.size() << " conductances; high electrode = ehigh (key " << net.high()
     << "), low electrode = 0 (key " << net.low() << ")\n";
  os << "* R values are 1/g; lines starting with '* floating:' are not connected to ehigh\n";
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const NetworkEdge &e = edges[k];
    if (!is_live(e.a)) os << "* floating: ";
    os << 'R' << (k + 1) << ' ' << spice_node_name(net, e.a) << ' ' << spice_node_name(net, e.b)
       << ' ' << num(1.0 / e.conductance) << '\n';
  }
  os << "I1 0 ehigh DC " << num(current) << '\n';
  os << ".op\n.end\n";
}

void write_spice_ac_netlist(std::ostream &os, std::vector<ComplexEdge> edges, NodeKey high,
                            NodeKey low, double current, double omega, const SpiceNodeNameFn &name,
                            const SpiceOptions &options)
{
  if (!(omega > 0.0)) throw std::invalid_argument("write_spice_ac_netlist: omega must be > 0");
  std::vector<NetworkEdge> plain;
  for (ComplexEdge &e : edges) {
    if (e.b < e.a) std::swap(e.a, e.b);
    if (e.y != std::complex<double>(0.0, 0.0)) plain.push_back({e.a, e.b, 1.0, 0.0, false});
  }
  std::sort(edges.begin(), edges.end(), [](const ComplexEdge &x, const ComplexEdge &y) {
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    if (x.y.real() != y.y.real()) return x.y.real() < y.y.real();
    return x.y.imag() < y.y.imag();
  });
  const std::vector<NodeKey> live = component_of(plain, high);
  auto is_live = [&](NodeKey k) { return std::binary_search(live.begin(), live.end(), k); };
  auto node = [&](NodeKey k) {
    return k == low ? std::string("0") : k == high ? "ehigh" : name(k);
  };
  const double f = omega / (2.0 * kPi);
  os << one_line(options.title) << '\n';
  os << "* " << edges.size() << " admittances G + j omega C at f = " << num(f)
     << " Hz; high electrode = ehigh, low electrode = 0\n";
  os << "* each as R = 1/G (none when G = 0) and C; lines starting with '* floating:' are not "
        "connected to ehigh\n";
  os << ".option rshunt=1e30\n";
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const ComplexEdge &e = edges[k];
    const std::string pre = is_live(e.a) ? "" : "* floating: ";
    const std::string ends = ' ' + node(e.a) + ' ' + node(e.b) + ' ';
    if (e.y.real() != 0.0) os << pre << 'R' << (k + 1) << ends << num(1.0 / e.y.real()) << '\n';
    if (e.y.imag() != 0.0) os << pre << 'C' << (k + 1) << ends << num(e.y.imag() / omega) << '\n';
  }
  os << "I1 0 ehigh AC " << num(current) << '\n';
  os << ".ac lin 1 " << num(f) << ' ' << num(f) << "\n.end\n";
}

void write_vtk_network(std::ostream &os, const ConductionNetwork &net, std::vector<VtkEdge> edges,
                       const VtkOptions &options)
{
  const std::size_t ns = options.edge_scalar_names.size();
  for (const VtkEdge &e : edges)
    if (e.scalars.size() != ns)
      throw std::invalid_argument("write_vtk_network: an edge has " +
                                  std::to_string(e.scalars.size()) + " scalars, expected " +
                                  std::to_string(ns) + " (one per edge_scalar_names entry)");
  std::sort(edges.begin(), edges.end(), edge_less);

  // Points in order of first use by the sorted edges.
  using PointId = std::pair<NodeKey, std::array<double, 3>>;
  std::map<PointId, int> index;
  std::vector<const PointId *> points;
  std::vector<std::array<int, 2>> cells;
  for (const VtkEdge &e : edges) {
    std::array<int, 2> c{};
    for (int s = 0; s < 2; ++s) {
      auto ins = index.emplace(PointId{s ? e.b : e.a, s ? e.pb : e.pa}, int(points.size()));
      if (ins.second) points.push_back(&ins.first->first);
      c[s] = ins.first->second;
    }
    cells.push_back(c);
  }

  os << "# vtk DataFile Version 3.0\n" << one_line(options.title) << "\nASCII\nDATASET POLYDATA\n";
  os << "POINTS " << points.size() << " double\n";
  for (const PointId *p : points)
    os << num(p->second[0]) << ' ' << num(p->second[1]) << ' ' << num(p->second[2]) << '\n';
  os << "LINES " << cells.size() << ' ' << 3 * cells.size() << '\n';
  for (const auto &c : cells) os << "2 " << c[0] << ' ' << c[1] << '\n';

  if (!points.empty()) {
    std::vector<std::string> pot, con;
    for (const PointId *p : points) {
      pot.push_back(num(net.potential(p->first)));
      con.push_back(net.is_connected(p->first) ? "1" : "0");
    }
    os << "POINT_DATA " << points.size() << '\n';
    write_scalars(os, "potential", "double", pot);
    write_scalars(os, "connected", "int", con);
  }
  if (!cells.empty()) {
    std::vector<std::string> g, cur, con;
    for (const VtkEdge &e : edges) {
      const bool on = net.is_connected(e.a) && net.is_connected(e.b);
      g.push_back(num(e.conductance));
      cur.push_back(num(on ? e.conductance * (net.potential(e.a) - net.potential(e.b)) : 0.0));
      con.push_back(on ? "1" : "0");
    }
    os << "CELL_DATA " << cells.size() << '\n';
    write_scalars(os, "conductance", "double", g);
    write_scalars(os, "current", "double", cur);
    write_scalars(os, "connected", "int", con);
    for (std::size_t s = 0; s < ns; ++s) {
      std::vector<std::string> vals;
      for (const VtkEdge &e : edges) vals.push_back(num(e.scalars[s]));
      write_scalars(os, vtk_name(options.edge_scalar_names[s]), "double", vals);
    }
  }
}

void write_vtk_network(std::ostream &os, const ConductionNetwork &net,
                       const NodePositionFn &position, const VtkOptions &options,
                       const EdgeScalarsFn &edge_scalars)
{
  std::vector<VtkEdge> out;
  for (const NetworkEdge &e : net.edges()) {
    VtkEdge v{e.a, e.b, e.conductance, {}, {}, {}};
    if (!position(e.a, v.pa) || !position(e.b, v.pb)) continue;
    v.scalars.assign(options.edge_scalar_names.size(), 0.0);
    if (edge_scalars) edge_scalars(e, v.scalars);
    out.push_back(std::move(v));
  }
  write_vtk_network(os, net, std::move(out), options);
}

}  // namespace ohmdem
