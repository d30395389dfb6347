// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix run/record (doc/fix_run_record.md). The record is read back from
   the restart file by deck_files json (restart keyword) before the run's run.json
   is written; restart() has nothing to restore.
------------------------------------------------------------------------- */

#include "OUTPUT/fix_run_record.h"

#include <fstream>
#include <sstream>

#include "comm.h"
#include "error.h"
#include "writers/run_record.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixRunRecord::FixRunRecord(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 4)
    error->all(FLERR,
               "fix run/record: expects one word after the style, FOLDER: the run's folder "
               "(its run.json and its run number)");
  folder_ = arg[3];
  restart_global = 1;
}

int FixRunRecord::setmask()
{
  return 0;
}

// At the start of every run: the run's number and its run.json as they are now (the deck
// writes run.json before its run).
void FixRunRecord::init()
{
  if (comm->me != 0) return;
  ohmdem::RunRecord r;
  r.run = ohmdem::folder_run_number(folder_);
  std::ifstream in(folder_ + "/run.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  r.parameters = text.str();
  record_ = ohmdem::encode_run_record(r);
}

void FixRunRecord::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const int size = static_cast<int>(record_.size());
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(record_.data(), 1, record_.size(), fp);
}

void FixRunRecord::restart(char *)
{
  // deck_files json reads the record from the file (before read_restart defines this fix)
}
