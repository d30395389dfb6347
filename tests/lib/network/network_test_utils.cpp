// SPDX-License-Identifier: GPL-2.0-or-later
#include "network_test_utils.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "conduction/conductance_laws.h"
#include "network/network_export.h"
#include "temp_dir.h"

namespace ohmdem_test {

namespace {

// splitmix64: a bijection, so distinct indices give distinct scrambled keys.
NodeKey scramble(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

RandomNetwork random_network(int nodes, int extra, double lg_min, double lg_max, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> lg(lg_min, lg_max);
  RandomNetwork net;
  for (int i = 0; i < nodes; ++i) net.keys.push_back(scramble(seed * 1000003ULL + i));
  auto g = [&]() { return std::pow(10.0, lg(rng)); };
  for (int i = 1; i < nodes; ++i) {
    std::uniform_int_distribution<int> pick(0, i - 1);
    net.edges.push_back({net.keys[i], net.keys[pick(rng)], g()});
  }
  std::uniform_int_distribution<int> any(0, nodes - 1);
  for (int k = 0; k < extra; ++k) {
    const int a = any(rng), b = any(rng);
    if (a != b) net.edges.push_back({net.keys[a], net.keys[b], g()});
  }
  return net;
}

RandomNetwork packing_network(int nx, int ny, int nz, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const double r = 1e-3, gamma = 5.88e7;
  const NodeKey high = ~NodeKey(0), low = ~NodeKey(0) - 1;
  const int lim[3] = {nx, ny, nz};
  const int up = nz > 1 ? 2 : 1;  // the axis along which the electrodes face each other
  auto id = [&](const int c[3]) { return std::uint32_t(1 + c[0] + nx * (c[1] + ny * c[2])); };
  // A contact's area belongs to the contact (both particles see the same one): draw it from
  // a hash of the contact, in [0.5, 2] * 1e-8 m^2.
  auto area = [&](NodeKey contact) {
    return 0.5e-8 + 1.5e-8 * double(scramble(contact ^ seed) >> 11) * 0x1p-53;
  };
  RandomNetwork out;
  out.keys = {high, low};
  ohmdem::ConductionNetwork particle;  // collects one particle's eq. 1 edges
  particle.set_electrodes(high, low);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int c[3] = {i, j, k};
        std::vector<ohmdem::ContactSpot> spots;
        for (int axis = 0; axis < 3; ++axis)
          for (int dir = -1; dir <= 1; dir += 2) {
            int n[3] = {c[0], c[1], c[2]};
            n[axis] += dir;
            ohmdem::ContactSpot s{};
            if (n[axis] >= 0 && n[axis] < lim[axis]) {
              s.node = ohmdem::contact_key(id(c), id(n));
              s.area = area(s.node);
            } else if (axis == up) {
              s.node = dir > 0 ? high : low;
              s.area = area(ohmdem::contact_side_key(id(c), 0));
            } else {
              continue;  // side walls do not conduct
            }
            s.point[axis] = dir * r * (1.0 + jitter(rng));
            for (int q = 0; q < 3; ++q)
              if (q != axis) s.point[q] = r * jitter(rng);
            spots.push_back(s);
          }
        ohmdem::ConductingParticle p{{0, 0, 0}, r, ohmdem::sphere_volume(r), gamma};
        particle.clear();
        ohmdem::add_particle_conductances(particle, p, spots.data(), spots.size());
        for (const ohmdem::NetworkEdge &e : particle.edges())
          out.edges.push_back({e.a, e.b, e.conductance});
      }
  std::vector<NodeKey> keys;
  for (const Edge &e : out.edges) {
    keys.push_back(e.a);
    keys.push_back(e.b);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (NodeKey k : keys)
    if (k != high && k != low) out.keys.push_back(k);
  return out;
}

RandomNetwork widened(RandomNetwork net, double decades, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5 * decades, 0.5 * decades);
  for (Edge &e : net.edges) e.g *= std::pow(10.0, u(rng));
  return net;
}

void add_all(ohmdem::ConductionNetwork &net, const std::vector<Edge> &edges)
{
  for (const Edge &e : edges) net.add_conductance(e.a, e.b, e.g);
}

ohmdem::NetworkSolution solve_with(const RandomNetwork &rn, ohmdem::SolverOptions o, double current)
{
  ohmdem::ConductionNetwork net;
  net.set_options(o);
  net.set_electrodes(rn.keys[0], rn.keys[1]);
  add_all(net, rn.edges);
  return net.solve(current);
}

RandomNetwork perturbed(const RandomNetwork &rn, double amplitude, std::uint64_t seed)
{
  RandomNetwork out = rn;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Edge &e : out.edges) e.g *= 1 + u(rng);
  return out;
}

ohmdem::SolverOptions kind(ohmdem::SolverKind k)
{
  ohmdem::SolverOptions o;
  o.kind = k;
  return o;
}

long double dense_resistance(const RandomNetwork &net)
{
  using M = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  using V = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  const int n = static_cast<int>(net.keys.size());
  auto idx = [&](NodeKey k) {
    return static_cast<int>(std::find(net.keys.begin(), net.keys.end(), k) - net.keys.begin());
  };
  // Unknowns: every node but keys[1] (grounded); keys[0] is unknown 0.
  M L = M::Zero(n - 1, n - 1);
  auto u = [&](int i) { return i == 0 ? 0 : (i == 1 ? -1 : i - 1); };
  for (const Edge &e : net.edges) {
    const int a = u(idx(e.a)), b = u(idx(e.b));
    const long double g = e.g;
    if (a >= 0) L(a, a) += g;
    if (b >= 0) L(b, b) += g;
    if (a >= 0 && b >= 0) {
      L(a, b) -= g;
      L(b, a) -= g;
    }
  }
  V rhs = V::Zero(n - 1);
  rhs[0] = 1;
  const V v = L.fullPivLu().solve(rhs);
  return v[0];
}

long double dense_kron_resistance(const RandomNetwork &net)
{
  const int n = static_cast<int>(net.keys.size());
  std::vector<std::vector<long double>> G(n, std::vector<long double>(n, 0.0L));
  auto idx = [&](NodeKey k) {
    return static_cast<int>(std::find(net.keys.begin(), net.keys.end(), k) - net.keys.begin());
  };
  for (const Edge &e : net.edges) {
    const int a = idx(e.a), b = idx(e.b);
    G[a][b] += e.g;
    G[b][a] += e.g;
  }
  // keys[0], keys[1] are the electrodes: eliminate everything else.
  for (int k = 2; k < n; ++k) {
    long double D = 0;
    for (int j = 0; j < n; ++j) D += G[k][j];
    if (D == 0) continue;
    for (int i = 0; i < n; ++i) {
      if (i == k || G[i][k] == 0) continue;
      for (int j = i + 1; j < n; ++j) {
        if (j == k || G[k][j] == 0) continue;
        const long double add = G[i][k] * G[k][j] / D;
        G[i][j] += add;
        G[j][i] += add;
      }
    }
    for (int i = 0; i < n; ++i) G[i][k] = G[k][i] = 0;
  }
  return 1 / G[0][1];
}

bool have_ngspice()
{
  return std::system("command -v ngspice >/dev/null 2>&1") == 0;
}

double ngspice_ehigh_voltage(const ohmdem::ConductionNetwork &net, double current,
                             const std::string &name, std::string &error)
{
  namespace fs = std::filesystem;
  // The test process's own temporary folder (removed at exit): CTest runs tests in parallel.
  const fs::path dir = ohmdem::test::temp_dir() / ("ngspice_" + name);
  fs::create_directories(dir);
  const fs::path cir = dir / "net.cir", raw = dir / "net.raw", log = dir / "ngspice.log";
  {
    std::ofstream f(cir);
    ohmdem::write_spice_netlist(f, net, current);
  }
  // An ASCII raw file carries 16 significant digits; the batch-mode listing only 6.
  const std::string cmd = "cd '" + dir.string() + "' && SPICE_ASCIIRAWFILE=1 ngspice -b -r '" +
                          raw.string() + "' '" + cir.string() + "' > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  double value = std::numeric_limits<double>::quiet_NaN();
  std::ifstream in(raw);
  std::string line;
  int var = -1, nvars = 0;
  bool values = false;
  std::vector<double> vals;
  while (std::getline(in, line)) {
    if (line.rfind("No. Variables:", 0) == 0) nvars = std::atoi(line.c_str() + 14);
    if (line.rfind("Values:", 0) == 0) {
      values = true;
      continue;
    }
    std::istringstream ls(line);
    if (!values) {
      int i;
      std::string vname;
      if (line.size() && line[0] == '\t' && (ls >> i >> vname) && vname == "v(ehigh)") var = i;
    } else {
      std::string tok;
      while (ls >> tok) vals.push_back(std::strtod(tok.c_str(), nullptr));
    }
  }
  // The value block starts with the point index, then one value per variable.
  if (var >= 0 && static_cast<int>(vals.size()) == nvars + 1) value = vals[var + 1];
  // ngspice reports singular matrices and failed gmin stepping as warnings but still writes a
  // result: treat any such warning as a failure.
  std::ifstream lg(log);
  std::stringstream all;
  all << lg.rdbuf();
  if (rc != 0 || all.str().find("singular") != std::string::npos ||
      all.str().find("rror") != std::string::npos) {
    error += "ngspice rc=" + std::to_string(rc) + "\n" + all.str();
    value = std::numeric_limits<double>::quiet_NaN();
  }
  if (std::isfinite(value)) fs::remove_all(dir);
  return value;
}

}  // namespace ohmdem_test
