// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command deck_files (doc/command_deck_files.md)

     deck_files mkdir PATH ...          every folder with its parents
     deck_files copy FROM TO            a file copied (replaced whole)
     deck_files restart FILE            FILE is a whole LIGGGHTS restart file
     deck_files lock FOLDER | unlock FOLDER   the output folder's lock
     deck_files hold FOLDER | release FOLDER  one process of the universe at a time in between
     deck_files exec PROGRAM ARG ...    a program run with these arguments
     deck_files json FILE string|number KEY VALUE ...   a flat JSON object, written whole

   LIGGGHTS' `shell` hands any line but cd/mkdir/mv/rm/rmdir/putenv to sh, so a
   deck variable in it (a path, a table cell) could run commands. Here no word
   ever reaches a shell: paths are system-call arguments, programs get their
   arguments as they are (posix_spawn). A word v_NAME is the value of the
   variable NAME, taken whole (a path with blanks stays one argument).
   Process 0 does the work; an error stops every process with its message.
------------------------------------------------------------------------- */

#include "OUTPUT/command_deck_files.h"

#include <mpi.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>

#include "comm.h"
#include "error.h"
#include "input.h"
#include "variable.h"
#include "writers/json_text.h"
#include "writers/run_folder.h"

extern char **environ;

using namespace LAMMPS_NS;

namespace {

const char *const kUsage =
    "deck_files: expects mkdir PATH..., copy FROM TO, restart FILE, lock FOLDER, unlock FOLDER, "
    "hold FOLDER, release FOLDER, exec PROGRAM ARG... or json FILE string|number KEY VALUE ...";

std::string host_name()
{
  char name[256] = {0};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

bool process_alive(long pid)
{
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

}  // namespace

DeckFiles::DeckFiles(LAMMPS *lmp) : Pointers(lmp) {}

void DeckFiles::command(int narg, char **arg)
{
  if (narg < 1) error->all(FLERR, kUsage);
  const std::string what = arg[0];
  std::vector<std::string> words;
  for (int i = 1; i < narg; ++i) words.push_back(value_of(arg[i]));
  const bool root = comm->me == 0;
  std::string message;

  if (what == "mkdir") {
    if (words.empty()) error->all(FLERR, "deck_files mkdir: expects one folder or more");
    for (const auto &path : words)
      if (root && message.empty()) message = ohmdem::make_folders(path);
    if (!message.empty() && words.size() == 1 && std::strncmp(arg[1], "v_", 2) == 0)
      message = std::string("deck variable ") + (arg[1] + 2) + ": " + message;
  } else if (what == "copy") {
    if (words.size() != 2) error->all(FLERR, "deck_files copy: expects FROM TO");
    if (root) message = ohmdem::copy_file(words[0], words[1]);
  } else if (what == "restart") {
    if (words.size() != 1) error->all(FLERR, "deck_files restart: expects one restart file");
    if (root) message = ohmdem::check_restart_file(words[0]);
    // The deck's variable named: the user gave it (-var restart_file FILE).
    if (!message.empty() && std::strncmp(arg[1], "v_", 2) == 0)
      message = std::string("deck variable ") + (arg[1] + 2) + ": " + message;
  } else if (what == "lock" || what == "unlock") {
    if (words.size() != 1) error->all(FLERR, "deck_files lock|unlock: expects one folder");
    if (root && what == "unlock") ohmdem::unlock_folder(words[0], ::getpid(), host_name());
    if (root && what == "lock") {
      const auto answer = ohmdem::lock_folder(words[0], ::getpid(), host_name(), process_alive);
      message = answer.error;
      if (!answer.note.empty()) error->warning(FLERR, ("deck_files: " + answer.note).c_str());
    }
  } else if (what == "hold" || what == "release") {
    if (words.size() != 1) error->all(FLERR, "deck_files hold|release: expects one folder");
    if (root && what == "hold") message = ohmdem::hold_turn(words[0]);
    if (root && what == "release") ohmdem::release_turn(words[0]);
  } else if (what == "json") {
    if (root) message = write_json(narg - 1, arg + 1);
  } else if (what == "exec") {
    if (words.empty()) error->all(FLERR, "deck_files exec: expects a program and its arguments");
    if (root) message = run_program(words);
  } else {
    error->all(FLERR, kUsage);
  }
  finish(message);
}

std::string DeckFiles::value_of(const char *word)
{
  if (std::strncmp(word, "v_", 2) != 0) return word;
  const char *value = input->variable->retrieve(const_cast<char *>(word + 2));
  if (!value) {
    const std::string msg = std::string("deck_files: no variable '") + (word + 2) + "' (" + word +
                            " gives a path or an argument)";
    error->all(FLERR, msg.c_str());
  }
  return value;
}

std::string DeckFiles::run_program(const std::vector<std::string> &argv)
{
  // The program writes to the same terminal and files: ours first.
  std::fflush(stdout);
  if (screen) std::fflush(screen);
  if (logfile) std::fflush(logfile);
  std::vector<std::string> copy(argv);
  std::vector<char *> args;
  for (auto &a : copy) args.push_back(a.data());
  args.push_back(nullptr);
  pid_t child = 0;
  const int err = posix_spawnp(&child, args[0], nullptr, nullptr, args.data(), environ);
  if (err != 0) return "deck_files exec: cannot run " + argv[0] + ": " + std::strerror(err);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  // As LIGGGHTS' shell: a helper that fails is said, the deck decides what follows.
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    error->warning(FLERR, ("deck_files exec: " + argv[0] + " ended with status " +
                           std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1))
                              .c_str());
  return "";
}

// FILE, then TYPE KEY VALUE triples: one writer quotes every string and checks every number
// (json_text.h); the file is replaced whole. A value v_NAME is the variable's value, whole.
std::string DeckFiles::write_json(int narg, char **arg)
{
  if (narg < 1) return "json: expects FILE, then string|number KEY VALUE ...";
  const std::string file = value_of(arg[0]);
  ohmdem::json::Object object;
  for (int i = 1; i < narg; i += 3) {
    const std::string type = arg[i];
    if (type != "string" && type != "number")
      return "json " + file + ": expected string or number before a key, got '" + type + "'";
    if (i + 2 >= narg) return "json " + file + ": " + type + " expects KEY VALUE";
    const std::string key = arg[i + 1], value = value_of(arg[i + 2]);
    try {
      if (type == "string")
        object.add_string(key, value);
      else
        object.add_number(key, value);
    } catch (const ohmdem::json::JsonError &e) {
      const std::string from = std::strncmp(arg[i + 2], "v_", 2) == 0
                                   ? std::string(" (deck variable ") + (arg[i + 2] + 2) + ")"
                                   : "";
      return "json " + file + ": " + e.what() + from;
    }
  }
  return ohmdem::replace_file(file, object.text() + "\n");
}

void DeckFiles::finish(std::string message)
{
  int length = static_cast<int>(message.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, 0, world);
  if (!message.empty()) error->all(FLERR, ("deck_files: " + message).c_str());
}
