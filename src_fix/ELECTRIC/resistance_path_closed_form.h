// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance, the closed form of a bearing: every conducting ball touches the
// high race, the low race, or both, and nothing else conducts. A ball with both contacts is
// one resistor between the electrodes (eq. 1 with its two spots, plus the two Holm
// constrictions if asked), and R is their parallel sum: no network, no gathering of contacts
// (doc/compute_network_resistance.md, "Solve": a particle with two contacts is one resistor).
// It evaluates the same model as the general network (electric/conduction_model.h), inline
// per ball, every step. Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_RESISTANCE_PATH_CLOSED_FORM_H
#define OHMDEM_STYLE_RESISTANCE_PATH_CLOSED_FORM_H

#include <vector>

#include "ELECTRIC/resistance_context.h"
#include "ELECTRIC/resistance_path.h"
#include "common/ordered_reduce.h"
#include "conduction/ball_between_races_3d.h"
#include "conduction/conduction_model.h"
#include "pointers.h"

namespace LAMMPS_NS {

class FixBearingRace;
class Atom;

// Model 3d: local atom i's resistances between races a and b, its spots as they are in space
// (resistance_path_closed_form_3d.cpp); with a == b, the ball facing that race on both sides
// (its spot and the point opposite).
ohmdem::BallResistances3d ball_between_3d(const ResistanceContext &context,
                                          const FixBearingRace &a, const FixBearingRace &b,
                                          const Atom &atom, int i);

class ClosedFormPath : public ResistancePath, protected Pointers {
 public:
  // Both electrodes of `context` are races; it outlives the path.
  ClosedFormPath(LAMMPS *lmp, const ResistanceContext &context);
  // False when a race that is neither electrode conducts somewhere (the general network
  // handles it).
  bool evaluate(double *phi, PathResult &result) override;
  // Each ball joining both races is one resistor carrying g_ball * V.
  void contact_flows(std::vector<ohmdem::ContactFlow> &rows) override;
  // Per local atom, the conductance of a ball joining both races at the last evaluation (NaN
  // for any other atom): the lubricated bearing's metallic path reads it instead of
  // computing it again.
  const double *ball_conductances() const { return g_local_.data(); }

 private:
  void set_geometry();  // at the first evaluation: the races' geometry is known then
  // Model 3d (resistance_path_closed_form_3d.cpp): each ball's spots as they are this step.
  bool evaluate_3d(double *phi, PathResult &result);
  void contact_flows_3d(std::vector<ohmdem::ContactFlow> &rows);

  const ResistanceContext &context_;
  bool geometry_ready_ = false;
  ohmdem::BallBetweenRaces between_races_;
  std::vector<const FixBearingRace *> other_races_;  // neither electrode: any contact -> network
  // Per local ball: conductance, 1 if it joins the races, 1 if a dead end.
  std::vector<ohmdem::TaggedValues<3> > balls_;
  ohmdem::OrderedGather<3> balls_gather_;
  std::vector<double> g_local_;
  double resistance_ = 0;  // of the last evaluation
};

}  // namespace LAMMPS_NS

#endif
