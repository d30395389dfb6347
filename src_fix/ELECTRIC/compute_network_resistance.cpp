// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance. The contacts come from ELECTRIC/contact_set.*,
   conductances from electric/, the solves from network/. This file checks, chooses the
   evaluation path at the start of a run (resistance_path.h) and reports; the keywords are
   read in compute_network_resistance_args.cpp, the exports are in network_exports.*, the
   local array in contact_flow_array.*.
------------------------------------------------------------------------- */

#include "ELECTRIC/compute_network_resistance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/contact_flow_array.h"
#include "ELECTRIC/contact_set.h"
#include "ELECTRIC/lubricated_network.h"
#include "ELECTRIC/network_exports.h"
#include "ELECTRIC/resistance_path_closed_form.h"
#include "ELECTRIC/resistance_path_distributed.h"
#include "ELECTRIC/resistance_path_gathered.h"
#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "group.h"
#include "input.h"
#include "lubrication/lubricant.h"
#include "memory.h"
#include "modify.h"
#include "network/conduction_network.h"
#include "support/require_si.h"
#include "update.h"
#include "variable.h"

using namespace LAMMPS_NS;

namespace {
constexpr int kVectorSize = 8;
// solver auto goes distributed from this many particles in the group (with more than one
// process and no export): measured crossover, bench/network_scale/README.md.
constexpr bigint kAutoDistributedParticles = 20000;
}  // namespace

ComputeNetworkResistance::ComputeNetworkResistance(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg),
      gathered_(std::make_unique<GatheredNetworkPath>(lmp, context_)),
      local_(std::make_unique<ContactFlowArray>(lmp))
{
  parse(narg, arg);
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = lube_.on() ? kVectorSize + LubricatedResult::kSize : kVectorSize;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
  local_flag = 1;  // per-contact rows (contact_flow_array.h)
  size_local_cols = ohmdem::ContactFlow::kColumns + (lube_.on() ? kLubricatedColumns : 0);
  size_local_rows = 0;
  vector = new double[size_vector];  // LIGGGHTS' Compute deletes it
  vector_atom = nullptr;
  array_local = nullptr;  // owned by local_
  contacts_ = std::make_unique<ContactSet>(
      lmp, id, area_exact_ ? ohmdem::AreaModel::Exact : ohmdem::AreaModel::Greenwood,
      pair_mode_ != 0);
  context_.contacts = contacts_.get();
  exports_ = std::make_unique<NetworkExports>(lmp, netlist_, vtk_, every_);
  if (lube_.on()) {
    try {
      lubricated_ = std::make_unique<LubricatedBearing>(lmp, lube_);
      lube_vtk_ = std::make_unique<LubricatedVtk>(lmp);
    } catch (const ohmdem::lubrication::LubricantError &e) {
      const std::string msg =
          std::string("compute network/resistance: keyword 'lubricant': ") + e.what();
      error->all(FLERR, msg.c_str());
    }
    if (lube_.breakdown_file) breakdown_text_ = std::to_string(lubricated_->state().breakdown);
  }
  if (lube_keyword_) define_lubricant_variables();
}

// With the keyword lubricant, what ran, for the deck (its signal columns and run.json):
// string variables lubricant_on (0 or 1) and, with a lubricant, lubricant_file,
// lubricant_path (closedform or network: how Z is evaluated), lubricant_eta0 (Pa s at the
// temperature), lubricant_alpha (1/Pa), lubricant_eps_r, lubricant_resistivity (ohm m).
void ComputeNetworkResistance::define_lubricant_variables()
{
  char buf[64];
  auto define = [&](const char *name, const std::string &value) {
    std::string words[3] = {name, "string", value};
    char *argv[3] = {words[0].data(), words[1].data(), words[2].data()};
    input->variable->set(3, argv);
  };
  define("lubricant_on", lubricated_ ? "1" : "0");
  define("lubricant_breakdown", lubricated_ ? breakdown_text_ : "0");  // the field in use
  if (!lubricated_) return;
  const ohmdem::lubrication::LubricantState &s = lubricated_->state();
  define("lubricant_file", lubricated_->path());
  define("lubricant_path", lube_.network ? "network" : "closedform");
  define("lubricant_kernel", ohmdem::lubrication::bearing_kernel_name(lube_.kernel));
  for (const auto &[name, value] : {std::pair<const char *, double>{"lubricant_eta0", s.eta},
                                    {"lubricant_alpha", s.alpha},
                                    {"lubricant_eps_r", s.eps_r},
                                    {"lubricant_resistivity", s.resistivity}}) {
    std::snprintf(buf, sizeof buf, "%.9g", value);
    define(name, buf);
  }
}

ComputeNetworkResistance::~ComputeNetworkResistance()
{
  memory->destroy(vector_atom);
}

void ComputeNetworkResistance::init()
{
  ohmdem::require_si_units(lmp, "compute network/resistance");
  // auto: particle–particle contacts when a granular pair style computes them.
  if (pair_mode_ < 0) pair_mode_ = 1;
  contacts_->init(groupbit);
  context_.groupbit = groupbit;
  resolve("high", context_.high);
  resolve("low", context_.low);
  read_conductivities();
  if (lubricated_) {
    if (!context_.races_are_electrodes())
      error->all(FLERR,
                 "compute network/resistance: keyword 'lubricant' needs both electrodes to be "
                 "races (high race ID low race ID): the lubricated closed form is a bearing's");
    if (contacts_->uses_pair())
      error->all(FLERR,
                 "compute network/resistance: keyword 'lubricant' needs pair no: particle-"
                 "particle contacts in oil are not modelled (a bearing's balls do not touch)");
    lubricated_->init(context_);
  }
  choose_paths();
  evaluated_step_ = -1;
  exports_->check_files();
}

void ComputeNetworkResistance::read_conductivities()
{
  auto *conductivity = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
      "electricalConductivity", "property/global", "peratomtype", atom->ntypes, 0, style));
  std::vector<double> &gamma_type = context_.gamma_type;
  gamma_type.assign(atom->ntypes + 1, 0.0);  // per atom type, 1-based
  for (int t = 1; t <= atom->ntypes; ++t) {
    const double g = conductivity->compute_vector(t - 1);
    gamma_type[t] = g;
    if (!(g >= 0.0) || !std::isfinite(g)) {
      const std::string msg = "compute network/resistance: electricalConductivity of type " +
                              std::to_string(t) + " must be >= 0 (S/m; 0 = insulator), got " +
                              std::to_string(g);
      error->all(FLERR, msg.c_str());
    }
  }
}

// The closed form when both electrodes are races and no pair contact can conduct (it still
// hands a step to the general network when a third race conducts, or for an export); the
// general network gathered, or distributed (solver distributed, or auto with several
// processes, no export and a large group: counted here, at the start of each run).
void ComputeNetworkResistance::choose_paths()
{
  closed_form_path_.reset();
  if (closed_form_ && context_.races_are_electrodes() && !contacts_->uses_pair())
    closed_form_path_ = std::make_unique<ClosedFormPath>(lmp, context_);
  ohmdem::SolverOptions opt = gathered_->options();
  opt.kind = static_cast<ohmdem::SolverKind>(solver_);
  opt.preconditioner =
      multigrid_ ? ohmdem::Preconditioner::Multigrid : ohmdem::Preconditioner::Diagonal;
  gathered_->set_options(opt, exports_->draws());
  bool distributed = distributed_solver_;
  if (!distributed && static_cast<ohmdem::SolverKind>(solver_) == ohmdem::SolverKind::Auto &&
      comm->nprocs > 1 && !exports_->any())
    distributed = group->count(igroup) >= kAutoDistributedParticles;
  if (distributed && !distributed_)
    distributed_ = std::make_unique<DistributedNetworkPath>(lmp, context_);
  network_path_ = distributed ? static_cast<ResistancePath *>(distributed_.get()) : gathered_.get();
  last_path_ = nullptr;
}

void ComputeNetworkResistance::evaluate()
{
  if (evaluated_step_ == update->ntimestep) return;
  evaluated_step_ = update->ntimestep;
  potentials_step_ = -1;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(vector_atom);
    memory->create(vector_atom, nmax_, "network/resistance:vector_atom");
  }
  // An export step needs the network itself (every: the other steps keep the closed form).
  PathResult r;
  if (closed_form_path_ && !exports_->due(update->ntimestep) &&
      closed_form_path_->evaluate(vector_atom, r)) {
    last_path_ = closed_form_path_.get();
  } else {
    network_path_->evaluate(vector_atom, r);
    last_path_ = network_path_;
  }
  report(r);
  const bool due = exports_->due(update->ntimestep);
  minima_step_ = impedance_step_ = -1;
  if (lubricated_) {
    lubricated_->evaluate(
        context_, due,
        last_path_ == closed_form_path_.get() ? closed_form_path_->ball_conductances() : nullptr);
    lube_result_ = LubricatedResult();  // its values when read: lube_impedance(), minima()
  }
  const bool draw_films = lubricated_ && due && exports_->draws();
  if (draw_films) lube_impedance();
  const VtkPartFn films = draw_films
                              ? lube_vtk_->gather(*lubricated_, context_, lube_result_.v_high)
                              : VtkPartFn();  // collective
  if (last_path_ == gathered_.get() && comm->me == 0) {
    // With a lubricant the netlist is the AC one of the impedance (lubricated_network.h).
    auto ac = [&](std::ostream &os) {
      lubricated_->network().write_netlist(os, context_.current, lubricated_->omega());
    };
    exports_->write(*gathered_, *contacts_, context_.current,
                    lubricated_ ? AcNetlistFn(ac) : AcNetlistFn(), films);
  }
}

void ComputeNetworkResistance::report(const PathResult &r)
{
  // The electrodes touch, and the model gives a contact spot no resistance (eq1: conduction
  // inside particles only): a short circuit, R = 0, said once; not "no conducting path".
  const double resistance = r.shorts > 0 ? 0.0 : r.resistance;
  if (r.shorts > 0 && !warned_short_ && comm->me == 0) {
    const auto atom_text = [](std::int64_t tag) {
      return tag > 0 ? "atom " + std::to_string(tag) : std::string("a race");
    };
    error->warning(
        FLERR,
        ("compute network/resistance: the electrodes touch: " + std::to_string(r.shorts) +
         " contact(s) join them directly (" + atom_text(r.short_tags[0]) + " and " +
         atom_text(r.short_tags[1]) +
         "), and model eq1 gives a contact spot no resistance: R = 0, a short circuit (model "
         "holm or eq1+holm adds the spots' constriction)")
            .c_str());
  }
  if (r.shorts > 0) warned_short_ = true;
  result_[0] = resistance;
  result_[1] = context_.current;
  result_[2] = resistance * context_.current;
  result_[3] = r.contacts;
  result_[4] = r.dropped;
  result_[5] = r.iterations;
  result_[6] = r.residual;
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

double ComputeNetworkResistance::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  evaluate();
  scalar = result_[0];
  return scalar;
}

// The impedance of the last evaluation into lube_result_, once per step that reads it.
void ComputeNetworkResistance::lube_impedance()
{
  if (impedance_step_ == update->ntimestep) return;
  lubricated_->impedance(lube_result_);
  impedance_step_ = update->ntimestep;
}

void ComputeNetworkResistance::compute_vector()
{
  invoked_vector = update->ntimestep;
  evaluate();
  std::copy(result_, result_ + kVectorSize, vector);
  if (lubricated_) {
    if (minima_step_ != update->ntimestep) {
      lubricated_->minima(lube_result_);  // collective, as compute_vector is
      minima_step_ = update->ntimestep;
    }
    lube_impedance();
    const LubricatedResult &l = lube_result_;
    const double extra[LubricatedResult::kSize] = {
        l.z_abs, l.z_phase, l.c_parallel, l.r_parallel, l.hmin_inner, l.hmin_outer, l.lambda_min};
    std::copy(extra, extra + LubricatedResult::kSize, vector + kVectorSize);
  }
}

void ComputeNetworkResistance::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  evaluate();
  // A path may leave them to here (the distributed one): only a reader pays for them.
  if (potentials_step_ != update->ntimestep) {
    last_path_->potentials(vector_atom);
    potentials_step_ = update->ntimestep;
  }
}

void ComputeNetworkResistance::compute_local()
{
  invoked_local = update->ntimestep;
  evaluate();
  if (lubricated_) lube_impedance();
  size_local_rows = lubricated_ ? local_->fill(*last_path_, context_, &lubricated_->contacts(),
                                               lube_result_.v_high)
                                : local_->fill(*last_path_, context_);
  array_local = local_->rows();
}

double ComputeNetworkResistance::memory_usage()
{
  double bytes = static_cast<double>(nmax_) * sizeof(double) + local_->memory_usage();
  for (const ResistancePath *p : {static_cast<const ResistancePath *>(closed_form_path_.get()),
                                  static_cast<const ResistancePath *>(gathered_.get()),
                                  static_cast<const ResistancePath *>(distributed_.get())})
    if (p) bytes += p->memory_usage();
  return bytes;
}
