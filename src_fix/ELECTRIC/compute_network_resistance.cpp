// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance. The contacts come from ELECTRIC/contact_set.*,
   conductances from conduction/, the solve from network/;
   this file parses, gathers the network from all processes and reports; the netlist and
   VTK exports are in compute_network_resistance_exports.cpp.
------------------------------------------------------------------------- */

#include "ELECTRIC/compute_network_resistance.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/compute_network_resistance_distributed.h"
#include "ELECTRIC/contact_set.h"
#include "atom.h"
#include "comm.h"
#include "common/constants.h"
#include "common/ordered_reduce.h"
#include "conduction/conductance_laws.h"
#include "conduction/network_builder.h"
#include "error.h"
#include "fix_property_global.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "network/conduction_network.h"
#include "network/network_export.h"
#include "support/args.h"
#include "support/require_si.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kVectorSize = 8;
}  // namespace

ComputeNetworkResistance::ComputeNetworkResistance(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg), network_(std::make_unique<ohmdem::ConductionNetwork>())
{
  parse(narg, arg);
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = kVectorSize;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
  local_flag = 1;  // per-contact rows (compute_network_resistance_local.cpp)
  size_local_cols = ohmdem::ContactFlow::kColumns;
  size_local_rows = 0;
  vector = new double[kVectorSize];  // LIGGGHTS' Compute deletes it
  vector_atom = nullptr;
  array_local = nullptr;  // LIGGGHTS' Compute leaves it unset: the destructor frees it
  contacts_ = std::make_unique<ContactSet>(
      lmp, id, area_exact_ ? ohmdem::AreaModel::Exact : ohmdem::AreaModel::Greenwood,
      pair_mode_ != 0);
}

ComputeNetworkResistance::~ComputeNetworkResistance()
{
  memory->destroy(vector_atom);
  memory->destroy(array_local);
}

void ComputeNetworkResistance::parse(int narg, char **arg)
{
  ohmdem::StyleArgs a(error, "compute network/resistance", narg, arg, 3);
  bool have_current = false, have_high = false, have_low = false;
  auto electrode = [&](const std::string &kw, Electrode &e) {
    const std::string kind = a.word(kw, "race FIX-ID or group GROUP-ID");
    if (kind == "race")
      e.kind = ElectrodeKind::Race;
    else if (kind == "group")
      e.kind = ElectrodeKind::Group;
    else
      a.fail(kw, "race FIX-ID or group GROUP-ID", kind.c_str());
    e.name = a.word(kw, "race FIX-ID or group GROUP-ID");
  };
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "current") {
      current_ = a.positive(kw, "the injected current I > 0 (A)");
      have_current = true;
    } else if (kw == "high") {
      electrode(kw, high_);
      have_high = true;
    } else if (kw == "low") {
      electrode(kw, low_);
      have_low = true;
    } else if (kw == "area") {
      const std::string m = a.word(kw, "greenwood or exact");
      if (m == "greenwood")
        area_exact_ = false;
      else if (m == "exact")
        area_exact_ = true;
      else
        a.fail(kw, "greenwood or exact", m.c_str());
    } else if (kw == "model") {
      const std::string names = ohmdem::model_names();
      const std::string m = a.word(kw, names.c_str());
      if (!ohmdem::find_model(m, model_)) a.fail(kw, names.c_str(), m.c_str());
    } else if (kw == "solver") {
      const std::string m = a.word(kw, "auto, direct, cg, amg or distributed");
      multigrid_ = m == "amg";
      distributed_solver_ = m == "distributed";
      if (m == "auto" || m == "distributed")
        solver_ = static_cast<int>(ohmdem::SolverKind::Auto);
      else if (m == "direct")
        solver_ = static_cast<int>(ohmdem::SolverKind::Direct);
      else if (m == "cg" || m == "amg")
        solver_ = static_cast<int>(ohmdem::SolverKind::ConjugateGradient);
      else
        a.fail(kw, "auto, direct, cg, amg or distributed", m.c_str());
    } else if (kw == "pair") {
      pair_mode_ = a.yes_no(kw) ? 1 : 0;
    } else if (kw == "netlist") {
      netlist_ = a.word(kw, "a file name");
    } else if (kw == "vtk") {
      vtk_ = a.word(kw, "a file name");
    } else if (kw == "every") {
      every_ = a.integer(kw, "a whole number of steps N >= 1", 1, std::numeric_limits<int>::max());
    } else if (kw == "closedform" || kw == "closed_form") {
      closed_form_ = a.yes_no(kw);
    } else {
      a.unknown(kw.c_str(),
                "current high low area model solver pair netlist vtk every closedform");
    }
  }
  if (!have_current) a.fail("current", "a value: the keyword is required", "nothing");
  if (!have_high)
    a.fail("high", "race FIX-ID or group GROUP-ID: the keyword is required", "nothing");
  if (!have_low) a.fail("low", "race FIX-ID or group GROUP-ID: the keyword is required", "nothing");
  if (distributed_solver_ && (!netlist_.empty() || !vtk_.empty()))
    a.fail("solver", "not distributed with netlist or vtk (the exports need the whole network "
                     "on one process)", "distributed");
  if (high_.kind == low_.kind && high_.name == low_.name)
    a.fail("low", "an electrode other than the high one", low_.name.c_str());
}

void ComputeNetworkResistance::init()
{
  ohmdem::require_si_units(lmp, "compute network/resistance");
  // auto: particle–particle contacts when a granular pair style computes them.
  if (pair_mode_ < 0) pair_mode_ = 1;
  contacts_->init(groupbit);
  auto resolve = [&](const char *kw, Electrode &e) {
    if (e.kind == ElectrodeKind::Race) {
      const auto &races = contacts_->races();
      e.index = -1;
      for (std::size_t k = 0; k < races.size(); ++k)
        if (e.name == races[k]->id) e.index = static_cast<int>(k);
      if (e.index < 0) {
        const std::string msg = std::string("compute network/resistance: keyword '") + kw +
                                "': no fix bearing/race with ID '" + e.name + "'";
        error->all(FLERR, msg.c_str());
      }
    } else {
      const int g = group->find(e.name.c_str());
      if (g < 0) {
        const std::string msg = std::string("compute network/resistance: keyword '") + kw +
                                "': no group '" + e.name + "'";
        error->all(FLERR, msg.c_str());
      }
      e.index = group->bitmask[g];
    }
  };
  resolve("high", high_);
  resolve("low", low_);
  conductivity_ = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
      "electricalConductivity", "property/global", "peratomtype", atom->ntypes, 0, style));
  gamma_type_.assign(atom->ntypes + 1, 0.0);  // per atom type, 1-based
  geometry_ready_ = false;
  for (int t = 1; t <= atom->ntypes; ++t) {
    const double g = conductivity_->compute_vector(t - 1);
    gamma_type_[t] = g;
    if (!(g >= 0.0) || !std::isfinite(g)) {
      const std::string msg = "compute network/resistance: electricalConductivity of type " +
                              std::to_string(t) + " must be >= 0 (S/m; 0 = insulator), got " +
                              std::to_string(g);
      error->all(FLERR, msg.c_str());
    }
  }
  ohmdem::SolverOptions opt = network_->options();
  opt.kind = static_cast<ohmdem::SolverKind>(solver_);
  opt.preconditioner =
      multigrid_ ? ohmdem::Preconditioner::Multigrid : ohmdem::Preconditioner::Diagonal;
  network_->set_options(opt);
  evaluated_step_ = -1;
  check_export_files();
}

void ComputeNetworkResistance::evaluate()
{
  if (evaluated_step_ == update->ntimestep) return;
  evaluated_step_ = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(vector_atom);
    memory->create(vector_atom, nmax_, "network/resistance:vector_atom");
  }
  closed_form_used_ = evaluate_between_races();
  if (!closed_form_used_) build_and_solve();
}

void ComputeNetworkResistance::report(double resistance, int contacts, int dropped, int iterations,
                                      double residual)
{
  result_[0] = resistance;
  result_[1] = current_;
  result_[2] = resistance * current_;
  result_[3] = contacts;
  result_[4] = dropped;
  result_[5] = iterations;
  result_[6] = residual;
  if (std::isfinite(resistance)) {
    had_path_ = true;
  } else if (had_path_) {
    // Conduction lost after it was established (a blow-up, a ring lifted off): said at the 1st,
    // 10th, 100th, ... such evaluation, and counted in output 8.
    ++lost_evaluations_;
    long long said = 1;
    while (said < lost_evaluations_) said *= 10;
    if (said == lost_evaluations_ && comm->me == 0) {
      const std::string msg = "compute network/resistance: conduction lost at step " +
                              std::to_string(update->ntimestep) +
                              ": no conducting path between the electrodes, R = inf (" +
                              std::to_string(lost_evaluations_) +
                              " evaluations so far; said at 1, 10, 100, ...)";
      error->warning(FLERR, msg.c_str());
    }
  } else if (!update->setupflag && !warned_no_path_) {
    // Never a path: said once, but not at the start of a run, where the balls of a bearing
    // start exactly touching and carry no current yet.
    if (comm->me == 0)
      error->warning(FLERR,
                     "compute network/resistance: no conducting path between the "
                     "electrodes: R = inf (said once)");
    warned_no_path_ = true;
  }
  result_[7] = static_cast<double>(lost_evaluations_);
}

// A bearing: every conducting ball touches the high race, the low race, or both, and nothing
// else conducts. A ball with both contacts is one resistor between the electrodes (eq. 1 with
// its two spots, plus the two Holm constrictions if asked), and R is their parallel sum: no
// network, no gathering of contacts (doc/compute_network_resistance.md, "Solve": a particle
// with two contacts is one resistor). Both this and the general network evaluate the same
// model (conduction/conduction_model.h). Returns false, on every process alike, when the scene
// is anything else.
bool ComputeNetworkResistance::evaluate_between_races()
{
  // An export step needs the network itself (every: the other steps keep the closed form).
  const bool export_step = (!netlist_.empty() || !vtk_.empty()) &&
                           (every_ == 0 || update->ntimestep % every_ == 0);
  if (!closed_form_ || export_step || high_.kind != ElectrodeKind::Race ||
      low_.kind != ElectrodeKind::Race || contacts_->uses_pair())
    return false;
  const auto &races = contacts_->races();
  if (!geometry_ready_) {
    between_races_ = ohmdem::BallBetweenRaces(
        model_, contacts_->race_geometry(high_.index), contacts_->race_geometry(low_.index),
        gamma_type_[races[high_.index]->race_type()], gamma_type_[races[low_.index]->race_type()],
        gamma_type_);
    other_races_.clear();
    for (int k = 0; k < static_cast<int>(races.size()); ++k)
      if (k != high_.index && k != low_.index) other_races_.push_back(races[k]);
    geometry_ready_ = true;
  }
  const ohmdem::BallBetweenRaces::Kernel model = between_races_.kernel();
  const double inf = std::numeric_limits<double>::infinity();

  // Local copies of LIGGGHTS' arrays: the loop stays in registers (this runs every step).
  const int nlocal = atom->nlocal;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const tagint *const tag = atom->tag;
  const double *const *const x = atom->x;
  const double *const radius = atom->radius;
  const FixBearingRace &race_hi = *races[high_.index];
  const FixBearingRace &race_lo = *races[low_.index];
  const double *const gamma_type = gamma_type_.data();
  const int bit = groupbit;
  double *const phi = vector_atom;  // potential / V_high, scaled once R is known

  balls_.resize(nlocal);
  ohmdem::TaggedValues<3> *out = balls_.data();
  int nballs = 0, other = 0;
  for (int i = 0; i < nlocal; ++i) {
    phi[i] = 0.0;
    if (!(mask[i] & bit)) continue;
    for (const FixBearingRace *race : other_races_)
      if (race->contact_of(i).conducts()) ++other;
    const ohmdem::RaceContactView ch = race_hi.contact_of(i), cl = race_lo.contact_of(i);
    const bool on_hi = ch.conducts(), on_lo = cl.conducts();
    const double gamma = gamma_type[type[i]];
    if (!(gamma > 0.0) || !(on_hi || on_lo)) continue;
    if (!(on_hi && on_lo)) {
      // A dead end: no current; its contact node sits at that electrode's potential.
      phi[i] = on_hi ? 1.0 : 0.0;
      out[nballs++] = {static_cast<std::int64_t>(tag[i]), {0.0, 0.0, 1.0}};
      continue;
    }
    const double u[3] = {ch.point_x() - x[i][0], ch.point_y() - x[i][1], 0.0};
    const double w[3] = {cl.point_x() - x[i][0], cl.point_y() - x[i][1], 0.0};
    const double conductance = model.conductance(type[i], gamma, radius[i], ch.fn(), cl.fn(), u, w);
    phi[i] = 0.5;
    out[nballs++] = {static_cast<std::int64_t>(tag[i]), {conductance, 1.0, 0.0}};
  }
  balls_.resize(nballs);
  int any_other = other;
  if (comm->nprocs > 1) MPI_Allreduce(&other, &any_other, 1, MPI_INT, MPI_SUM, world);
  if (any_other) return false;  // a third conducting race: the general network handles it

  // Conductances added in tag order: the same R with any number of processes.
  const auto sum = ohmdem::ordered_sum<3>(balls_gather_.gather(balls_, world));
  const double conductance = sum[0];
  const int paths = static_cast<int>(sum[1]), dead = static_cast<int>(sum[2]);
  const double resistance = conductance > 0.0 ? 1.0 / conductance : inf;
  report(resistance, 2 * paths + dead, 0, 0, 0.0);
  // Per-atom potential: mean of the contact-node potentials (the electrodes' own).
  const double v_high = std::isfinite(resistance) ? resistance * current_ : 0.0;
  for (int i = 0; i < nlocal; ++i) phi[i] *= v_high;
  return true;
}

// The particles and contacts of all processes, in tag order: the same network, and the same
// numbers, for any process count.
void ComputeNetworkResistance::gather_scene(std::vector<ohmdem::ParticleRecord> &particles,
                                            std::vector<ohmdem::ContactRecord> &contacts)
{
  std::vector<ContactSet::Contact> local;
  contacts_->collect(local);
  const int high_bit = high_.kind == ElectrodeKind::Group ? high_.index : 0;
  const int low_bit = low_.kind == ElectrodeKind::Group ? low_.index : 0;
  std::vector<ohmdem::ParticleRecord::Packed> my_particles;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int m = atom->mask[i];
    const auto member = (m & high_bit)  ? ohmdem::Membership::High
                        : (m & low_bit) ? ohmdem::Membership::Low
                                        : ohmdem::Membership::None;
    my_particles.push_back(ohmdem::ParticleRecord{static_cast<std::int64_t>(atom->tag[i]),
                                                  {atom->x[i][0], atom->x[i][1], atom->x[i][2]},
                                                  atom->radius[i],
                                                  atom->type[i],
                                                  member}
                               .pack());
  }
  std::vector<ohmdem::ContactRecord::Packed> my_contacts;
  for (const auto &c : local)
    my_contacts.push_back(ohmdem::ContactRecord{static_cast<std::int64_t>(c.tag1),
                                                static_cast<std::int64_t>(c.tag2),
                                                c.race,
                                                c.fn,
                                                {c.point[0], c.point[1], c.point[2]},
                                                c.ellipse.a,
                                                c.ellipse.b}
                              .pack());
  const auto all_particles = ohmdem::gather_by_tag<6>(my_particles, world);
  particles.resize(all_particles.size());
  for (std::size_t k = 0; k < all_particles.size(); ++k)
    particles[k] = ohmdem::ParticleRecord::unpack(all_particles[k]);
  const auto all_contacts = ohmdem::gather_by_tag<8>(my_contacts, world);
  contacts.resize(all_contacts.size());
  for (std::size_t k = 0; k < all_contacts.size(); ++k)
    contacts[k] = ohmdem::ContactRecord::unpack(all_contacts[k]);
}

void ComputeNetworkResistance::build_and_solve()
{
  distributed_used_ = use_distributed();
  if (distributed_used_) return solve_distributed();
  // The scene in members: their memory is reused from step to step.
  gather_scene(particles_, contact_records_);
  gamma_race_.clear();
  for (const FixBearingRace *r : contacts_->races())
    gamma_race_.push_back(gamma_type_[r->race_type()]);

  // The model's conductances: constrictions across contacts, the bulk law inside particles.
  ohmdem::ConductionNetwork &net = *network_;
  const ohmdem::NetworkScene scene{&particles_, &contact_records_, &gamma_type_, &gamma_race_,
                                   !vtk_.empty()};
  ohmdem::NetworkBuild &built = built_;
  ohmdem::build_network(model_, scene, net, built);

  // Solve: current into `high`, `low` at 0 V.
  auto electrode_node = [&](const Electrode &e, ohmdem::Membership member) {
    return e.kind == ElectrodeKind::Race ? ohmdem::race_node(e.index) : ohmdem::member_node(member);
  };
  net.set_electrodes(electrode_node(high_, ohmdem::Membership::High),
                     electrode_node(low_, ohmdem::Membership::Low));
  const ohmdem::NetworkSolution sol = net.solve(current_);
  report(sol.resistance, built.conducting_contacts, sol.floating_nodes_dropped, sol.iterations,
         sol.relative_residual);

  // Per-atom potential: mean over the particle's contact nodes (0 without a contact).
  const auto &spots = built.spots;
  for (int i = 0; i < atom->nlocal; ++i) {
    vector_atom[i] = 0.0;
    if (!(atom->mask[i] & groupbit)) continue;
    const std::int64_t tag = atom->tag[i];
    auto lo = std::lower_bound(
        spots.begin(), spots.end(), tag,
        [](const ohmdem::NetworkBuild::Spot &x, std::int64_t t) { return x.tag < t; });
    double sum = 0.0;
    int n = 0;
    for (; lo != spots.end() && lo->tag == tag; ++lo, ++n) sum += net.potential(lo->spot.node);
    vector_atom[i] = n ? sum / n : 0.0;
  }
  if (comm->me == 0) write_exports(built.drawn);
}

double ComputeNetworkResistance::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  evaluate();
  scalar = result_[0];
  return scalar;
}

void ComputeNetworkResistance::compute_vector()
{
  invoked_vector = update->ntimestep;
  evaluate();
  std::copy(result_, result_ + kVectorSize, vector);
}

void ComputeNetworkResistance::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  evaluate();
  // The distributed solve leaves them to here: only a reader pays for them.
  if (distributed_used_ && !closed_form_used_ && potentials_step_ != update->ntimestep) {
    distributed_->potentials(groupbit, vector_atom);
    potentials_step_ = update->ntimestep;
  }
}

double ComputeNetworkResistance::memory_usage()
{
  return static_cast<double>(nmax_) * sizeof(double) +
         static_cast<double>(local_capacity_) * ohmdem::ContactFlow::kColumns * sizeof(double) +
         (distributed_ ? distributed_->memory_usage() : 0.0);
}
