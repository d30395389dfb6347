// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - compute network/resistance: its keywords (doc/compute_network_resistance.md,
   Syntax), each checked as it is read with a message naming it and the expected form, and
   the electrodes' names resolved at init() to a race fix or a group.
------------------------------------------------------------------------- */

#include <limits>
#include <string>
#include <vector>

#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/compute_network_resistance.h"
#include "ELECTRIC/contact_set.h"
#include "error.h"
#include "group.h"
#include "network/conduction_network.h"
#include "support/args.h"

using namespace LAMMPS_NS;

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
      context_.current = a.positive(kw, "the injected current I > 0 (A)");
      have_current = true;
    } else if (kw == "high") {
      electrode(kw, context_.high);
      have_high = true;
    } else if (kw == "low") {
      electrode(kw, context_.low);
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
      if (!ohmdem::find_model(m, context_.model)) a.fail(kw, names.c_str(), m.c_str());
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
    } else if (kw == "lubricant") {
      lube_.lubricant = a.word(kw, "a lubricant name of inputs/lubricants, a file, or none");
      lube_keyword_ = true;
    } else if (kw == "temperature") {
      lube_.temperature = a.number(kw, "the oil temperature (C)");
    } else if (kw == "roughness") {
      lube_.roughness = a.positive(kw, "the composite RMS roughness sigma > 0 (m)");
    } else if (kw == "fexc") {
      lube_.fexc = a.positive(kw, "the excitation frequency > 0 (Hz)");
    } else if (kw == "wetted") {
      lube_.wetted = a.positive(kw, "the wetted radius around a contact > 0 (m)");
    } else if (kw == "excitation") {
      lube_.excitation = a.positive(kw, "the voltage amplitude across the bearing > 0 (V)");
    } else if (kw == "kernel") {
      const std::string name = a.word(kw, ohmdem::lubrication::kBearingKernelNames);
      if (!ohmdem::lubrication::bearing_kernel_named(name, lube_.kernel))
        a.fail(kw, ohmdem::lubrication::kBearingKernelNames, name.c_str());
    } else if (kw == "breakdown") {
      lube_.breakdown_file = a.next_is("lubricant");
      breakdown_text_ = a.peek();  // a number as written, for run.json
      if (lube_.breakdown_file)
        a.word(kw, "lubricant");
      else
        lube_.breakdown = a.non_negative(kw, "the film's breakdown field >= 0 (V/m; 0: none)");
    } else {
      a.unknown(kw.c_str(),
                "current high low area model solver pair netlist vtk every closedform "
                "lubricant temperature roughness fexc wetted excitation breakdown kernel");
    }
  }
  lube_.network = !closed_form_;  // the lubricated impedance follows closedform too
  // Read only with a lubricant (so that a deck passes them whatever it runs, as fix
  // bearing/defect ignores the keywords its kind does not use); required then.
  if (lube_.on()) {
    if (!(lube_.roughness > 0.0))
      a.fail("roughness", "a value with a lubricant: the keyword is required", "nothing");
    if (!(lube_.fexc > 0.0))
      a.fail("fexc", "a value with a lubricant: the keyword is required", "nothing");
    if (!(lube_.wetted > 0.0))
      a.fail("wetted", "a value with a lubricant: the keyword is required", "nothing");
  }
  if (!have_current) a.fail("current", "a value: the keyword is required", "nothing");
  if (!have_high)
    a.fail("high", "race FIX-ID or group GROUP-ID: the keyword is required", "nothing");
  if (!have_low) a.fail("low", "race FIX-ID or group GROUP-ID: the keyword is required", "nothing");
  if (distributed_solver_ && (!netlist_.empty() || !vtk_.empty()))
    a.fail("solver",
           "not distributed with netlist or vtk (the exports need the whole network "
           "on one process)",
           "distributed");
  const Electrode &high = context_.high, &low = context_.low;
  if (high.kind == low.kind && high.name == low.name)
    a.fail("low", "an electrode other than the high one", low.name.c_str());
}

void ComputeNetworkResistance::resolve(const char *kw, Electrode &e)
{
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
}
