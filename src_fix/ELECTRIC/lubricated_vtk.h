// SPDX-License-Identifier: GPL-2.0-or-later
// compute network/resistance with a lubricant and `vtk`: the lubricated contacts of an export
// step as a companion file (BASE_lubricated[.STEP].vtk, part 3 of the .pvd): one point per
// ball-race contact at its contact point, with the film (h_central, h_min, lambda), the
// admittance (C, G) and the contact's current phasor (|I|, phase) as point data
// (doc/compute_network_resistance.md). Reads the records LubricatedBearing made; computes
// nothing of the contact physics. Adapter code (LIGGGHTS types).
#ifndef OHMDEM_STYLE_LUBRICATED_VTK_H
#define OHMDEM_STYLE_LUBRICATED_VTK_H

#include <complex>
#include <functional>
#include <iosfwd>
#include <vector>

#include "common/ordered_reduce.h"
#include "pointers.h"

namespace LAMMPS_NS {

class LubricatedBearing;
struct ResistanceContext;
// Writes one companion VTK file of an export step (network_exports.h).
using VtkPartFn = std::function<void(std::ostream &)>;

class LubricatedVtk : protected Pointers {
 public:
  explicit LubricatedVtk(LAMMPS *lmp) : Pointers(lmp) {}
  // Collective, on an export step after the bearing's evaluation: gathers every process's
  // records in tag order (the same file with any number of processes). v_high: the high
  // electrode's phasor Z I. Returns the writer process 0 hands to NetworkExports::write.
  VtkPartFn gather(const LubricatedBearing &bearing, const ResistanceContext &context,
                   std::complex<double> v_high);

 private:
  // Per record: side, loaded, contact point x y z, h_central, h_min, lambda, C, G, Re Y, Im Y.
  static constexpr int kValues = 12;
  void write(std::ostream &os, std::complex<double> v_high) const;
  std::vector<ohmdem::TaggedValues<kValues>> local_, all_;
};

}  // namespace LAMMPS_NS

#endif
