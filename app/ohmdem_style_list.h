// SPDX-License-Identifier: GPL-2.0-or-later
// The styles of src_fix/ (BEARING/, ELECTRIC/, OUTPUT/), one line each. No include guard on
// purpose: this list is included once for the class declarations and again with FIX_CLASS /
// COMPUTE_CLASS / COMMAND_CLASS defined, where each header expands to its FixStyle(...) /
// ComputeStyle(...) / CommandStyle(...)
// line (the LAMMPS style-header convention). Adding a style = adding its header here.
#include "BEARING/command_bearing_catalog.h"
#include "BEARING/fix_bearing_cage.h"
#include "BEARING/fix_bearing_defect.h"
#include "BEARING/fix_bearing_race.h"
#include "ELECTRIC/compute_contact_area.h"
#include "ELECTRIC/compute_network_contacts.h"
#include "ELECTRIC/compute_network_resistance.h"
#include "OUTPUT/command_check_variables.h"
#include "OUTPUT/command_deck_files.h"
#include "OUTPUT/fix_run_record.h"
#include "OUTPUT/fix_signal_table.h"
