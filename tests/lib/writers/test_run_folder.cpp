// SPDX-License-Identifier: GPL-2.0-or-later
// The files around a run without a shell (src_fix/lib/writers/run_folder.*): folders with their
// parents and their length limits, the lock of an output folder, the restart file check on a
// file built here in LIGGGHTS 3.8's write_restart layout (header flags 0..48, then -1; the atoms
// as chunks of an int N and N doubles, each atom's values starting with their count).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "temp_dir.h"
#include "writers/run_folder.h"

using ohmdem::test::temp_path;

namespace {

bool is_dir(const std::string &p)
{
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

template <class T>
void put(std::string &s, T v)
{
  s.append(reinterpret_cast<const char *>(&v), sizeof v);
}
void put_text(std::string &s, const std::string &t)
{
  put<int>(s, static_cast<int>(t.size() + 1));
  s.append(t.c_str(), t.size() + 1);
}

// The part of a restart file before its atoms: the header (a box of -10..10 m), 40 bytes of
// groups, types and force fields (not checked), then the fixes' sections as LIGGGHTS writes
// them: -1, one fix with a 32-byte state, one per-atom fix.
std::string restart_head(int natoms, int nprocs = 1)
{
  std::string s;
  for (int flag = 0; flag <= 48; ++flag) {
    put<int>(s, flag);
    if (flag == 0)
      put_text(s, "Version LIGGGHTS-PUBLIC 3.8.0");
    else if (flag == 4)
      put_text(s, "si");
    else if (flag == 22)
      put_text(s, "sphere");
    else if (flag == 5 || flag == 23 || flag == 25 || flag == 28 || flag == 31 || flag == 34)
      put<std::int64_t>(s, flag == 23 ? natoms : 0);
    else if (flag >= 37)
      put<double>(s, flag <= 42 ? (flag % 2 ? -10.0 : 10.0) : 0.5);
    else
      put<int>(s, flag == 7 ? nprocs : 1);  // nprocs (flag 7) and every other int
  }
  put<int>(s, -1);
  s += std::string(40, '\0');  // groups, types, force fields: not checked
  put<int>(s, -1);
  put<int>(s, 1);
  put_text(s, "signal");
  put_text(s, "signal/table");
  put<int>(s, 32);
  for (int k = 0; k < 4; ++k) put<double>(s, 0.001 * k);
  put<int>(s, 1);
  put_text(s, "contacthistory");
  put_text(s, "contacthistory");
  put<int>(s, 2);
  return s;
}

// One process's atoms: FIRST..FIRST+N-1, 5 values each (count, x, y, z, one more).
std::string atom_chunk(int first, int n)
{
  std::string s;
  put<int>(s, n * 5);
  for (int a = first; a < first + n; ++a)
    for (int v = 0; v < 5; ++v) put<double>(s, v == 0 ? 5.0 : 0.25 * a);
  return s;
}

// A restart file of NATOMS atoms of 5 values each, in one chunk.
std::string restart_bytes(int natoms)
{
  return restart_head(natoms) + atom_chunk(0, natoms);
}

std::string write(const std::string &name, const std::string &bytes)
{
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

}  // namespace

TEST(RunFolder, MakesParentsAndAcceptsExisting)
{
  const std::string path = temp_path("a") + "/b/c";
  EXPECT_EQ(ohmdem::make_folders(path), "");
  EXPECT_TRUE(is_dir(path));
  EXPECT_EQ(ohmdem::make_folders(path), "");
  EXPECT_EQ(ohmdem::make_folders(path + "/"), "");
}

TEST(RunFolder, RefusesAFileInTheWay)
{
  const std::string file = write("plain_file", "x");
  const std::string msg = ohmdem::make_folders(file + "/sub");
  EXPECT_NE(msg.find("is not a folder"), std::string::npos) << msg;
}

TEST(RunFolder, RefusesLongPathsBeforeTheSystemDoes)
{
  const std::string msg = ohmdem::make_folders(temp_path("") + std::string(PATH_MAX, 'x'));
  EXPECT_NE(msg.find("PATH_MAX"), std::string::npos) << msg;
  const std::string comp = ohmdem::make_folders(temp_path(std::string(300, 'y')));
  EXPECT_NE(comp.find("NAME_MAX"), std::string::npos) << comp;
  EXPECT_NE(ohmdem::make_folders(""), "");
}

TEST(RunFolder, CopiesWhole)
{
  const std::string from = write("copy_from", std::string("abc\0def", 7));
  ASSERT_EQ(ohmdem::copy_file(from, temp_path("copy_to")), "");
  std::ifstream in(temp_path("copy_to"), std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), std::string("abc\0def", 7));
  EXPECT_NE(ohmdem::copy_file(temp_path("none"), temp_path("x")), "");
}

TEST(RunFolder, LockRefusesALiveHolderAndReplacesAStaleOne)
{
  const std::string dir = temp_path("locked");
  ASSERT_EQ(ohmdem::make_folders(dir), "");
  auto alive = [](long pid) { return pid == 111; };
  EXPECT_EQ(ohmdem::lock_folder(dir, 111, "h1", alive).error, "");
  EXPECT_EQ(ohmdem::lock_folder(dir, 111, "h1", alive).error, "");  // ours again
  const auto busy = ohmdem::lock_folder(dir, 222, "h1", alive);
  EXPECT_NE(busy.error.find("live run of pid 111"), std::string::npos) << busy.error;
  const auto remote = ohmdem::lock_folder(dir, 222, "h2", alive);
  EXPECT_NE(remote.error.find("on host h1"), std::string::npos) << remote.error;
  ohmdem::unlock_folder(dir, 222, "h1");  // not its lock: kept
  EXPECT_NE(ohmdem::lock_folder(dir, 222, "h1", alive).error, "");
  // The holder ended without unlocking (SIGKILL): stale, replaced.
  auto none_alive = [](long) { return false; };
  const auto stale = ohmdem::lock_folder(dir, 222, "h1", none_alive);
  EXPECT_EQ(stale.error, "");
  EXPECT_NE(stale.note.find("stale"), std::string::npos);
  ohmdem::unlock_folder(dir, 222, "h1");
  EXPECT_EQ(ohmdem::lock_folder(dir, 333, "h1", alive).note, "");  // no lock left
}

// A lock written on another host: its pid cannot be checked here, so even a pid that does
// not run on this host leaves it held, and the error says why; run.json's owner test too.
TEST(RunFolder, LockFromAnotherHostIsNeverStale)
{
  const std::string dir = temp_path("locked_remote");
  ASSERT_EQ(ohmdem::make_folders(dir), "");
  auto none_alive = [](long) { return false; };
  EXPECT_FALSE(ohmdem::locked_by_another(dir, 7, "here"));  // no lock at all
  EXPECT_EQ(ohmdem::lock_folder(dir, 111, "there", none_alive).error, "");
  const auto remote = ohmdem::lock_folder(dir, 111, "here", none_alive);
  EXPECT_NE(remote.error.find("on host there"), std::string::npos) << remote.error;
  EXPECT_NE(remote.error.find("not judged stale"), std::string::npos) << remote.error;
  EXPECT_EQ(remote.note, "");
  EXPECT_TRUE(ohmdem::locked_by_another(dir, 111, "here"));
  EXPECT_FALSE(ohmdem::locked_by_another(dir, 111, "there"));
}

// Another process's view of FOLDER's turn: true when it could take it now (flock LOCK_NB in a
// child process, which then exits: its descriptor, and any flock it took, goes with it).
bool turn_free_for_another_process(const std::string &folder)
{
  const pid_t child = ::fork();
  if (child == 0) {
    const int fd = ::open((folder + "/.ohmdem.turn").c_str(), O_RDWR);
    ::_exit(fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0 ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

TEST(RunFolder, TurnHoldsOutOtherProcessesUntilReleased)
{
  const std::string dir = temp_path("turn");
  ASSERT_EQ(ohmdem::make_folders(dir), "");
  ohmdem::release_turn(dir);  // not held: nothing
  ASSERT_EQ(ohmdem::hold_turn(dir), "");
  EXPECT_EQ(ohmdem::hold_turn(dir), "");  // held already: goes on
  EXPECT_FALSE(turn_free_for_another_process(dir));
  ohmdem::release_turn(dir);
  EXPECT_TRUE(turn_free_for_another_process(dir));
  ohmdem::release_turn(dir);              // twice: nothing
  ASSERT_EQ(ohmdem::hold_turn(dir), "");  // again, after the release
  EXPECT_FALSE(turn_free_for_another_process(dir));
  ohmdem::release_turn(dir);
}

// A process that dies holding the turn (a killed partition) leaves it free: the kernel drops
// its flock with its descriptors, so hold_turn here returns instead of waiting for ever.
TEST(RunFolder, TurnOfADeadHolderIsFree)
{
  const std::string dir = temp_path("turn_dead");
  ASSERT_EQ(ohmdem::make_folders(dir), "");
  const pid_t child = ::fork();
  if (child == 0) {
    const bool held = ohmdem::hold_turn(dir).empty();
    ::raise(SIGKILL);  // dies holding it
    ::_exit(held ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(ohmdem::hold_turn(dir), "");
  ohmdem::release_turn(dir);
}

TEST(RunFolder, TurnInAFolderThatIsNotThereSaysWhy)
{
  const std::string message = ohmdem::hold_turn(temp_path("turn_missing") + "/no/such/folder");
  EXPECT_NE(message.find("cannot open the turn file"), std::string::npos) << message;
  EXPECT_NE(message.find(".ohmdem.turn"), std::string::npos) << message;
}

TEST(RunFolder, RestartCheckAcceptsAWholeFile)
{
  EXPECT_EQ(ohmdem::check_restart_file(write("whole.restart", restart_bytes(13))), "");
}

TEST(RunFolder, RestartCheckRefusesEveryCut)
{
  const std::string whole = restart_bytes(13);
  // every length from 0 to the whole file less one byte
  for (std::size_t n = 0; n < whole.size(); n += (n < 300 ? 1 : 7)) {
    const std::string msg = ohmdem::check_restart_file(write("cut.restart", whole.substr(0, n)));
    EXPECT_NE(msg.find("cut.restart"), std::string::npos) << "length " << n << ": " << msg;
  }
  EXPECT_NE(ohmdem::check_restart_file(write("cut1.restart", whole.substr(0, whole.size() - 1))),
            "");
}

TEST(RunFolder, RestartCheckRefusesOtherFiles)
{
  EXPECT_NE(ohmdem::check_restart_file(temp_path("missing.restart")).find("no file"),
            std::string::npos);
  EXPECT_NE(ohmdem::check_restart_file(temp_path("")), "");  // a folder
  std::string other = restart_bytes(13);
  std::memcpy(&other[8], "Version LAMMPS  ", 16);
  EXPECT_NE(ohmdem::check_restart_file(write("other.restart", other)).find("LIGGGHTS version"),
            std::string::npos);
  // the header's atom count differs from the atoms the file holds
  std::string fewer = restart_bytes(13);
  const std::string twelve = restart_bytes(12);
  EXPECT_EQ(fewer.size() - twelve.size(), 40u);
  std::string liar = twelve;
  const std::size_t at = liar.find(std::string("\x17\0\0\0", 4));
  ASSERT_NE(at, std::string::npos);
  const std::int64_t thirteen = 13;
  std::memcpy(&liar[at + 4], &thirteen, 8);
  EXPECT_NE(ohmdem::check_restart_file(write("liar.restart", liar)).find("12 atoms"),
            std::string::npos);
}

// Damage in the middle of the file, where the header and the atom counts still agree: the
// fixes' sections, an atom moved out of the box, a value that is no number.
TEST(RunFolder, RestartCheckRefusesDamageInTheMiddle)
{
  const std::string whole = restart_bytes(13);
  const std::size_t fixes = whole.find("signal/table");
  ASSERT_NE(fixes, std::string::npos);
  std::string size = whole;
  const int wrong = 40;  // the fix's state size: 32
  std::memcpy(&size[fixes + 13], &wrong, 4);
  EXPECT_NE(ohmdem::check_restart_file(write("mid_size.restart", size)).find("fixes' sections"),
            std::string::npos);
  std::string id = whole;
  id[whole.find("signal") + 6] = 'x';  // its NUL gone
  EXPECT_NE(ohmdem::check_restart_file(write("mid_id.restart", id)).find("fixes' sections"),
            std::string::npos);
  const std::size_t atoms = whole.size() - 13 * 5 * 8;
  std::string far = whole;
  const double out = 99.0;
  std::memcpy(&far[atoms + 8 * (5 * 4 + 2)], &out, 8);  // atom 5's y
  EXPECT_NE(ohmdem::check_restart_file(write("mid_far.restart", far)).find("atom 5 lies outside"),
            std::string::npos);
  std::string nan = whole;
  const double q = std::nan("");
  std::memcpy(&nan[atoms + 8 * (5 * 7 + 4)], &q, 8);
  EXPECT_NE(ohmdem::check_restart_file(write("mid_nan.restart", nan)).find("not a number"),
            std::string::npos);
}

// write_restart FILE.% (one file per process): FILE.base with the header and the fixes,
// FILE.0 and FILE.1 with the atoms. Whole: accepted; a part missing or cut: refused by name.
TEST(RunFolder, RestartCheckReadsMultiFileRestarts)
{
  write("multi.base", restart_head(13, 2));
  write("multi.0", atom_chunk(0, 6));
  write("multi.1", atom_chunk(6, 7));
  const std::string pattern = temp_path("multi.%");
  EXPECT_EQ(ohmdem::check_restart_file(pattern), "");
  write("multi.1", atom_chunk(6, 7).substr(0, 100));
  EXPECT_NE(ohmdem::check_restart_file(pattern).find("multi.1, its atoms are cut"),
            std::string::npos)
      << ohmdem::check_restart_file(pattern);
  write("multi.1", atom_chunk(6, 6));
  EXPECT_NE(ohmdem::check_restart_file(pattern).find("12 atoms, its header says 13"),
            std::string::npos);
  std::remove(temp_path("multi.1").c_str());
  EXPECT_NE(ohmdem::check_restart_file(pattern).find("process 1"), std::string::npos);
  EXPECT_NE(ohmdem::check_restart_file(temp_path("none.%")).find("none.base"), std::string::npos);
}
