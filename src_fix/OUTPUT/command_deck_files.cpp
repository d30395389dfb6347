// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - command deck_files (doc/command_deck_files.md)

     deck_files mkdir PATH ...          every folder with its parents
     deck_files copy FROM TO            a file copied (replaced whole)
     deck_files restart FILE            FILE is a whole LIGGGHTS restart file
     deck_files lock FOLDER | unlock FOLDER   the output folder's lock
     deck_files hold FOLDER | release FOLDER  one process of the universe at a time in between
     deck_files exec PROGRAM ARG ...    a program run with these arguments
     deck_files json FILE [restart R changes yes|no] string|number KEY VALUE ...
                                        a flat JSON object, written whole (a continued run's
                                        restart R checked first)
     deck_files newrun FOLDER FILE ...  a new run in FOLDER: the previous run's FILEs set aside

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
#include "writers/run_record.h"

extern char **environ;

using namespace LAMMPS_NS;

namespace {

const char *const kUsage =
    "deck_files: expects mkdir PATH..., copy FROM TO, restart FILE, lock FOLDER, unlock FOLDER, "
    "hold FOLDER, release FOLDER, exec PROGRAM ARG..., json FILE string|number KEY VALUE ... or "
    "newrun FOLDER FILE...";

std::string host_name()
{
  char name[256] = {0};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

constexpr double kLockWait = 5.0;  // seconds

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
      // a holder that is ending (a run just stopped) is waited for, briefly
      const auto answer =
          ohmdem::lock_folder(words[0], ::getpid(), host_name(), process_alive, kLockWait);
      message = answer.error;
      if (!answer.note.empty()) error->warning(FLERR, ("deck_files: " + answer.note).c_str());
    }
  } else if (what == "hold" || what == "release") {
    if (words.size() != 1) error->all(FLERR, "deck_files hold|release: expects one folder");
    if (root && what == "hold") message = ohmdem::hold_turn(words[0]);
    if (root && what == "release") ohmdem::release_turn(words[0]);
  } else if (what == "json") {
    if (root) message = write_json(narg - 1, arg + 1);
    // With restart: what changed, on every process, for the deck's next writes of the file.
    if (narg >= 6 && std::strcmp(arg[2], "restart") == 0) {
      finish(message);
      share_changes();
      return;
    }
  } else if (what == "newrun") {
    if (words.empty()) error->all(FLERR, "deck_files newrun: expects FOLDER [FILE ...]");
    if (root) message = begin_run(words);
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
// FILE, [restart RFILE changes yes|no,] then TYPE KEY VALUE triples: one writer quotes every
// string and checks every number (json_text.h); the file is replaced whole. A value v_NAME is
// the variable's value, whole. With restart, the run continued from RFILE is checked first
// against the run RFILE records (run_record.h); nothing is written when it is refused.
std::string DeckFiles::write_json(int narg, char **arg)
{
  if (narg < 1) return "json: expects FILE, then string|number KEY VALUE ...";
  const std::string file = value_of(arg[0]);
  int first = 1;
  const char *restart_word = nullptr, *changes_word = nullptr;
  if (narg >= 5 && std::strcmp(arg[1], "restart") == 0 && std::strcmp(arg[3], "changes") == 0) {
    restart_word = arg[2];
    changes_word = arg[4];
    first = 5;
  }
  ohmdem::json::Object object;
  for (int i = first; i < narg; i += 3) {
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
  if (restart_word) {
    const std::string refused = check_continued_run(file, restart_word, changes_word, object);
    if (!refused.empty()) return refused;
  }
  return ohmdem::replace_file(file, object.text() + "\n");
}

namespace {
std::string folder_of(const std::string &file)
{
  const std::size_t slash = file.rfind('/');
  return slash == std::string::npos ? "." : file.substr(0, slash);
}
std::string named(const char *word, const std::string &value)
{
  return std::strncmp(word, "v_", 2) == 0 ? std::string("deck variable ") + (word + 2) : value;
}
}  // namespace

// A run continued from a restart file: the run it records must be the folder's last run (or
// the folder has none yet), and its parameters this run's; else the continuation is refused
// unless the change is meant (changes yes), and run.json then says what changed.
std::string DeckFiles::check_continued_run(const std::string &file, const char *restart_word,
                                           const char *changes_word, ohmdem::json::Object &object)
{
  const std::string restart = value_of(restart_word), meant = value_of(changes_word);
  if (meant != "yes" && meant != "no")
    return named(changes_word, "changes") + ": expected yes or no, got '" + meant + "'";
  const std::string folder = folder_of(file);
  std::string state;
  bool found = false;
  const std::string bad = ohmdem::restart_fix_state(restart, "run/record", state, found);
  if (!bad.empty()) return named(restart_word, "restart") + ": " + bad;
  ohmdem::RunRecord record;
  if (!found || !ohmdem::decode_run_record(state, record)) {
    error->warning(FLERR, ("deck_files json: the restart file " + restart +
                           " records no run (written before runs were recorded, or by a deck "
                           "without fix run/record): its run and parameters are not compared")
                              .c_str());
    return "";
  }
  const long last = ohmdem::folder_run_number(folder);
  const bool other_run = last != 0 && record.run != last;
  std::vector<ohmdem::ParameterChange> changes;
  try {
    changes = ohmdem::changed_parameters(record.parameters, object.members());
  } catch (const ohmdem::json::JsonError &e) {
    error->warning(FLERR, ("deck_files json: the run recorded in " + restart +
                           " has no readable parameters (" + e.what() + "): they are not compared")
                              .c_str());
  }
  std::string what;
  for (const auto &c : changes)
    what += (what.empty() ? "" : ", ") + c.key + " " + (c.before.empty() ? "(none)" : c.before) +
            " -> " + (c.after.empty() ? "(none)" : c.after);
  if (!other_run && changes.empty()) {
    if (last == 0) return ohmdem::set_folder_run_number(folder, record.run);
    return "";
  }
  const std::string run_text =
      other_run ? "it was written by run " + std::to_string(record.run) + " of its folder, and " +
                      folder + "'s last run is run " + std::to_string(last) +
                      " (another run's restart: its state does not continue that run's signal)"
                : "";
  if (meant != "yes")
    return named(restart_word, "restart") + ": " + restart + ": " + run_text +
           (other_run && !what.empty() ? "; " : "") +
           (what.empty() ? ""
                         : "its run had other parameters (the restart's -> this run's): " + what) +
           ". Continue with the restart's own run and parameters, or say that the change is "
           "meant: " +
           (std::strncmp(changes_word, "v_", 2) == 0
                ? std::string("-var ") + (changes_word + 2) + " yes"
                : std::string("changes yes"));
  changed_ = (other_run ? "restart of run " + std::to_string(record.run) + " (the folder's run " +
                              std::to_string(last) + ")" + (what.empty() ? "" : "; ")
                        : "") +
             what;
  nchanged_ = static_cast<int>(changes.size()) + (other_run ? 1 : 0);
  object.insert_string("time_reached", "restart_changes", changed_);
  return ohmdem::set_folder_run_number(folder, record.run);
}

// The variables restart_changed (what changed, "" for nothing) and restart_nchanged (how
// many), for the deck's later writes of run.json.
void DeckFiles::share_changes()
{
  int n[2] = {static_cast<int>(changed_.size()), nchanged_};
  MPI_Bcast(n, 2, MPI_INT, 0, world);
  changed_.resize(static_cast<std::size_t>(n[0]));
  MPI_Bcast(changed_.data(), n[0], MPI_CHAR, 0, world);
  const std::string count = std::to_string(n[1]);
  for (const auto &[name, value] :
       {std::pair<std::string, std::string>{"restart_changed", changed_},
        {"restart_nchanged", count}}) {
    std::string words[3] = {name, "string", value};
    char *set[3] = {words[0].data(), words[1].data(), words[2].data()};
    input->variable->set(3, set);
  }
}

// A new run in FOLDER: its number up by one, the previous run's FILEs renamed NAME.previous.
std::string DeckFiles::begin_run(const std::vector<std::string> &words)
{
  long run = 0;
  std::vector<std::string> renamed;
  const std::vector<std::string> files(words.begin() + 1, words.end());
  const std::string bad = ohmdem::begin_new_run(words[0], files, run, renamed);
  if (!bad.empty()) return "newrun: " + bad;
  if (!renamed.empty()) {
    std::string list;
    for (const auto &f : renamed) list += (list.empty() ? "" : ", ") + f;
    const std::string line = "deck_files: a new run (run " + std::to_string(run) + ") in " +
                             words[0] + ": the previous run's " + list +
                             " renamed NAME.previous (a resume never takes them for this run's)\n";
    if (screen) std::fputs(line.c_str(), screen);
    if (logfile) std::fputs(line.c_str(), logfile);
  }
  return "";
}

void DeckFiles::finish(std::string message)
{
  int length = static_cast<int>(message.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, 0, world);
  if (!message.empty()) error->all(FLERR, ("deck_files: " + message).c_str());
}
