// SPDX-License-Identifier: GPL-2.0-or-later
// Restart files written whole or not at all.
//
// LIGGGHTS 3.8's WriteRestart::write opens the file itself and never checks its writes: a full
// disk while the bearing deck wrote restart.a, then restart.b, left both at 0 bytes, exit 0,
// no word, and the run had no restart left to continue from. The executable defines
// WriteRestart::write, as it does the error exits (app/liggghts_errors.cpp): libliggghts calls
// it through the PLT for the `restart` command's periodic files, `write_restart` and the
// restart forced by SIGINT/SIGTERM. It runs LIGGGHTS' own writer (dlsym(RTLD_NEXT)) on
// FILE.writing, checks that file whole (the checks of deck_files restart,
// src_fix/lib/writers/run_folder.h), and only then renames it to FILE: the previous FILE
// survives any failure, and the run stops naming the file and the reason. A multi-file restart
// (FILE with a `%`) is written as LIGGGHTS writes it.
//
// Reading one, LIGGGHTS' ReadRestart::header() prints the file's version ("version 3 8") with
// printf, on standard output, past -screen none; that one line is filtered out below.
#include <dlfcn.h>
#include <mpi.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "error.h"
#include "write_restart.h"
#include "writers/run_folder.h"

using namespace LAMMPS_NS;

namespace {

// What the file system of PATH still holds, for the message ("" when unknown).
std::string free_space(const std::string &path)
{
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  struct statvfs fs {};
  if (::statvfs(dir.c_str(), &fs) != 0) return "";
  const unsigned long long bytes =
      static_cast<unsigned long long>(fs.f_bavail) * static_cast<unsigned long long>(fs.f_frsize);
  return bytes < 65536 ? ", its file system is full (" + std::to_string(bytes) + " bytes free)"
                       : "";
}

}  // namespace

void WriteRestart::write(char *file)
{
  using Original = void (*)(WriteRestart *, char *);
  static const auto original =
      reinterpret_cast<Original>(dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS12WriteRestart5writeEPc"));
  if (!original) {
    std::fprintf(stderr, "ohmdem: cannot find WriteRestart::write in libliggghts (%s)\n",
                 dlerror());
    std::abort();
  }
  if (std::strchr(file, '%')) {
    original(this, file);
    return;
  }
  const std::string target = file;
  std::string temporary = target + ".writing";
  original(this, temporary.data());  // every process: the atoms are gathered to process 0
  int rank = 0;
  MPI_Comm_rank(world, &rank);
  std::string message;
  if (rank == 0) {
    std::string bad = ohmdem::check_restart_file(temporary);
    const std::string kept = ::access(file, F_OK) == 0 ? "the previous " + target + " is kept"
                                                       : "no earlier " + target + " existed";
    if (!bad.empty()) {
      // the checker's reason, after its "... is damaged or not a LIGGGHTS restart file: "
      const std::size_t why = bad.find("restart file: ");
      if (why != std::string::npos) bad = bad.substr(why + 14);
      message = "restart file " + target + " was not written whole (" + bad + ")" +
                free_space(target) + ": " + kept;
    } else if (std::rename(temporary.c_str(), target.c_str()) != 0) {
      message = "restart file " + target + " cannot replace the previous one (" +
                std::strerror(errno) + "): " + kept;
    }
    if (!message.empty()) std::remove(temporary.c_str());
  }
  int length = static_cast<int>(message.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  message.resize(static_cast<std::size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, 0, world);
  if (!message.empty()) error->all(FLERR, message.c_str());
}

// libliggghts is built with _FORTIFY_SOURCE: its printf calls are __printf_chk, through the
// PLT, so this definition (exported with -rdynamic) is the one they reach. Everything but
// ReadRestart::header()'s version line is printed as glibc prints it.
extern "C" int __vprintf_chk(int flag, const char *format, va_list ap);
extern "C" int __printf_chk(int flag, const char *format, ...)
{
  if (std::strcmp(format, "version %d %d\n") == 0) return 0;
  va_list ap;
  va_start(ap, format);
  const int n = __vprintf_chk(flag, format, ap);
  va_end(ap);
  return n;
}
