// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricated bearing's general network; see lubricated_network.h.
#include "ELECTRIC/lubricated_network.h"

#include <ostream>
#include <string>

#include "ELECTRIC/lubricated_bearing.h"
#include "network/network_export.h"

using namespace LAMMPS_NS;

namespace {

// Electrode keys below 2^32 (conduction_network.h); a ball's node above them.
constexpr ohmdem::NodeKey kHigh = ohmdem::electrode_key(1), kLow = ohmdem::electrode_key(2);
ohmdem::NodeKey ball_key(std::int64_t tag)
{
  return static_cast<ohmdem::NodeKey>(tag) << 32;
}

}  // namespace

void LubricatedNetwork::gather(const std::vector<LubricatedContact> &local, MPI_Comm comm)
{
  local_.clear();
  for (const LubricatedContact &c : local)
    local_.push_back({c.tag, {static_cast<double>(c.side), c.y.real(), c.y.imag()}});
  edges_.clear();
  for (const ohmdem::TaggedValues<3> &r : gather_.gather(local_, comm))
    edges_.push_back({r.v[0] == 0.0 ? kHigh : kLow, ball_key(r.tag), {r.v[1], r.v[2]}});
}

std::complex<double> LubricatedNetwork::solve(double current) const
{
  return ohmdem::solve_complex_network(edges_, kHigh, kLow, current).z;
}

void LubricatedNetwork::write_netlist(std::ostream &os, double current, double omega) const
{
  ohmdem::SpiceOptions o;
  o.title = "ohmdem lubricated bearing (AC)";
  ohmdem::write_spice_ac_netlist(
      os, edges_, kHigh, kLow, current, omega,
      [](ohmdem::NodeKey k) { return "b" + std::to_string(k >> 32); }, o);
}
