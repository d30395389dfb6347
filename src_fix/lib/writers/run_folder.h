// SPDX-License-Identifier: GPL-2.0-or-later
// The files a deck handles around a run, without a shell: the output folder with its parents
// (lengths checked first), a file copied, a restart file checked before read_restart, and the
// output folder's lock (two live runs never share one folder). Each function returns "" when
// it succeeded, else the message for the user, naming the path. Plain C++: no LIGGGHTS types.
#ifndef OHMDEM_RUN_FOLDER_H
#define OHMDEM_RUN_FOLDER_H

#include <cstddef>
#include <functional>
#include <string>

namespace ohmdem {

// Room kept below PATH_MAX for the names of the files a run writes into its folder
// (restart_forced_liggghts_STEP.data is the longest).
constexpr std::size_t kRunFileNameRoom = 64;

// "" when PATH (a folder that will hold the run's files) is short enough: the whole path
// leaves kRunFileNameRoom below PATH_MAX and no component exceeds NAME_MAX.
std::string check_folder_path(const std::string &path);

// mkdir -p PATH: every missing folder along the path (an existing folder is fine).
std::string make_folders(const std::string &path);

// Copies FROM to TO (replaced whole: written beside it, then renamed).
std::string copy_file(const std::string &from, const std::string &to);

// Writes TEXT to PATH, replacing it whole: written beside it (PATH.tmpPID), then renamed, so
// that PATH is never half-written; the message names PATH and the system's reason (ENOSPC).
std::string replace_file(const std::string &path, const std::string &text);

// A file written by LIGGGHTS 3.8's write_restart: it exists, is a regular file, and its
// header can be read to its end marker (every section whole, the flags known ones). A file
// cut anywhere before the end of its header, or not a restart file, is refused here:
// read_restart itself loops forever on a cut header.
std::string check_restart_file(const std::string &path);

// The global state that the first fix of STYLE wrote into the restart file PATH (`found`
// false when it has none, or the file is above the size check_restart_file reads); the
// message of check_restart_file when the file is not whole.
std::string restart_fix_state(const std::string &path, const std::string &style,
                              std::string &state, bool &found);

// The lock of an output folder: FOLDER/.ohmdem.lock holds "pid PID host HOST". A lock held by
// a live process (kill(pid, 0)), or written on another host (its process cannot be checked),
// refuses the folder; a lock of this process is taken again; a lock of a process that no
// longer runs on this host is stale and replaced (`note` says so).
struct LockAnswer {
  std::string error;  // "" when the lock is ours now
  std::string note;   // a stale lock replaced
};
// A live holder on this host is waited for up to `wait_seconds` (checked every 0.1 s): the
// processes of a run just stopped with SIGTERM take a moment to end, and a resume started
// right after would otherwise meet one of them.
LockAnswer lock_folder(const std::string &folder, long pid, const std::string &host,
                       const std::function<bool(long)> &alive, double wait_seconds = 0);
// Removes FOLDER's lock when it is PID's on HOST (another holder's lock is left alone).
void unlock_folder(const std::string &folder, long pid, const std::string &host);
std::string lock_path(const std::string &folder);
// True when FOLDER's lock names another holder than PID on HOST: that run's run.json is not
// this process's to rewrite (a second run refused by the lock must leave it alone).
bool locked_by_another(const std::string &folder, long pid, const std::string &host);

// A turn in FOLDER: one process at a time between hold_turn and release_turn (an exclusive
// flock on FOLDER/.ohmdem.turn). The wait blocks without polling, and the kernel ends the turn
// of a process that dies holding it. The partitions of a sweep take turns at LIGGGHTS' `next`
// of a universe variable, whose rename lock sleeps 100 s whenever two ask at once. Returns ""
// or the reason the turn could not be taken; release_turn of a turn not held does nothing.
std::string hold_turn(const std::string &folder);
void release_turn(const std::string &folder);

}  // namespace ohmdem

#endif
