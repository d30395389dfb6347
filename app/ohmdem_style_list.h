// The styles of src_fix/, one line each. No include guard on purpose: this list is
// included once for the class declarations and again with FIX_CLASS / COMPUTE_CLASS
// defined, where each header expands to its FixStyle(...) / ComputeStyle(...) line
// (the LAMMPS style-header convention). Adding a style = adding its header here.
#include "fix_bearing_race.h"
#include "fix_bearing_cage.h"
#include "compute_network_resistance.h"
#include "compute_contact_area.h"
#include "fix_bearing_defect.h"
#include "fix_signal_table.h"
