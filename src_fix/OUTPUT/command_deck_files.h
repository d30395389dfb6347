// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command deck_files: the files and helper programs of a deck
   without a shell (doc/command_deck_files.md).
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS

// clang-format off
CommandStyle(deck_files,DeckFiles)
// clang-format on

#else

#ifndef LMP_DECK_FILES_COMMAND_H
#define LMP_DECK_FILES_COMMAND_H

#include <string>
#include <vector>

#include "pointers.h"
#include "writers/json_text.h"

namespace LAMMPS_NS {

class DeckFiles : protected Pointers {
 public:
  explicit DeckFiles(LAMMPS *lmp);
  void command(int narg, char **arg);

 private:
  // WORD, or the whole value of the variable V when WORD is v_V.
  std::string value_of(const char *word);
  // Process 0's answer ("" or an error message) on every process; an error stops the run.
  void finish(std::string message);
  std::string run_program(const std::vector<std::string> &argv);
  std::string write_json(int narg, char **arg);
  std::string check_continued_run(const std::string &file, const char *restart_word,
                                  const char *changes_word, ohmdem::json::Object &object);
  void share_changes();
  std::string begin_run(const std::vector<std::string> &words);
  std::string changed_;  // what a continued run changed (process 0)
  int nchanged_ = 0;
};

}  // namespace LAMMPS_NS

#endif
#endif
