// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix run/record: the run that writes a restart file, recorded in it (the
   run's number in its folder and its run.json), so that a resume from another run's
   restart, or with other parameters, is seen (doc/fix_run_record.md).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(run/record,FixRunRecord)
// clang-format on

#else

#ifndef LMP_FIX_RUN_RECORD_H
#define LMP_FIX_RUN_RECORD_H

#include <string>

#include "fix.h"

namespace LAMMPS_NS {

class FixRunRecord : public Fix {
 public:
  FixRunRecord(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  std::string folder_;
  std::string record_;  // process 0: the bytes written into restart files
};

}  // namespace LAMMPS_NS

#endif
#endif
