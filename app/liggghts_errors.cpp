// SPDX-License-Identifier: GPL-2.0-or-later
// LIGGGHTS' error exits without the "tip of the day".
//
// LIGGGHTS-PUBLIC 3.8's Error::all, one, universe_all, universe_one, fix_error and
// compute_error add, after the ERROR line and in about one error in ten, a "tip of the day" or
// "comment from the off" (SpecialMessages::generate_message in error_special.h). That function
// returns the c_str() of a string it has already destroyed, so the line printed is freed memory:
// arbitrary bytes in the log and on the screen stream (a test that reads the output as UTF-8
// fails; valgrind reports the read). The executable defines these members itself, as it does
// LAMMPS::post_create (app/ohmdem_styles.cpp): libliggghts calls them through the PLT, so these
// definitions (exported with -rdynamic) are the ones used. Each does what LIGGGHTS' does, in
// the same order and with the same messages, without the extra line. Beyond LIGGGHTS: an error
// raised on one process (Error::one) also reaches the world's log, from whichever process it
// is (LIGGGHTS writes it to that process's screen stream only: lost with -screen none), and
// every error's message is kept for run.json (app/run_status.h).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "compute.h"
#include "error.h"
#include "fix.h"
#include "lammps.h"
#include "output.h"
#include "run_status.h"
#include "universe.h"

using namespace LAMMPS_NS;

namespace {

// Messages of two characters or fewer are LIGGGHTS' "illegal command" shorthand.
bool says_something(const char *str)
{
  return str && std::strlen(str) > 2;
}

// The end of an error raised by every process of one world (Error::all's, as LIGGGHTS orders
// it): the output (dumps, restarts) closed, the world's files closed, MPI ended, exit 1. With
// several worlds (partitions) LIGGGHTS aborted the universe: one bad case of a sweep killed the
// cases of every other partition. Here the world's processes leave alone: MPI_Finalize waits
// for the other worlds to end theirs, and the universe's screen says which partition stopped.
[[noreturn]] void end_world(LAMMPS *lmp, const char *str)
{
  Universe *u = lmp->universe;
  if (u->nworlds > 1 && u->uscreen && str) {
    int me = 0;
    MPI_Comm_rank(lmp->world, &me);
    if (me == 0)
      std::fprintf(u->uscreen,
                   "ERROR on partition %d: %s (its processes stop; the other partitions go on)\n",
                   u->iworld + 1, str);
    std::fflush(u->uscreen);
  }
  delete lmp->output;  // LIGGGHTS owns it; its destructor closes dumps and restarts
  lmp->output = nullptr;
  if (lmp->screen && lmp->screen != stdout) std::fclose(lmp->screen);
  if (lmp->logfile) std::fclose(lmp->logfile);
  MPI_Finalize();
  std::exit(1);
}

}  // namespace

// Called by every process of the universe: the message once, all files closed, no abort.
void Error::universe_all(const char *file, int line, const char *str)
{
  ohmdem::note_error(str);
  MPI_Barrier(universe->uworld);
  if (universe->me == 0) {
    if (universe->uscreen) std::fprintf(universe->uscreen, "ERROR: %s (%s:%d)\n", str, file, line);
    if (universe->ulogfile)
      std::fprintf(universe->ulogfile, "ERROR: %s (%s:%d)\n", str, file, line);
  }
  if (output) delete output;  // LIGGGHTS owns it; its destructor closes dumps and restarts
  if (universe->nworlds > 1) {
    if (screen && screen != stdout) std::fclose(screen);
    if (logfile) std::fclose(logfile);
  }
  if (universe->ulogfile) std::fclose(universe->ulogfile);
  MPI_Finalize();
  std::exit(1);
}

// Called by one process: the universe is aborted.
void Error::universe_one(const char *file, int line, const char *str)
{
  ohmdem::note_error(str);
  char text[1024];
  std::snprintf(text, sizeof text, "ERROR on proc %d: %s (%s:%d)\n", universe->me, str, file, line);
  if (universe->uscreen) std::fputs(text, universe->uscreen);
  if (universe->ulogfile) std::fputs(text, universe->ulogfile);
  MPI_Abort(universe->uworld, 1);
}

// Called by every process of one world.
void Error::all(const char *file, int line, const char *str)
{
  ohmdem::note_error(str);
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    if (screen) std::fprintf(screen, "ERROR: %s (%s:%d)\n", str, file, line);
    if (logfile) std::fprintf(logfile, "ERROR: %s (%s:%d)\n", str, file, line);
  }
  end_world(lmp, str);
}

// Called by one process of a world: the world (and the universe) is aborted.
void Error::one(const char *file, int line, const char *str)
{
  int me = 0;
  MPI_Comm_rank(world, &me);
  ohmdem::note_error(str);
  char text[1024];
  std::snprintf(text, sizeof text, "ERROR on proc %d: %s (%s:%d)\n", me, str, file, line);
  if (screen) std::fputs(text, screen);
  // The world's log: process 0 holds it open; another process appends to it by its path.
  if (logfile)
    std::fputs(text, logfile);
  else
    ohmdem::append_to_log(text);
  // A world of one process (a partition of a sweep) has no other process to wait for: it
  // leaves alone, as after Error::all; a larger world must abort (its other processes may
  // be waiting for this one in a collective).
  int size = 1;
  MPI_Comm_size(world, &size);
  if (universe->nworlds > 1 && size == 1) end_world(lmp, str);  // run.json: at exit()
  if (universe->nworlds > 1 && universe->uscreen)
    std::fprintf(universe->uscreen, "ERROR on proc %d: %s (%s:%d)\n", universe->me, str, file,
                 line);
  MPI_Abort(world, 1);
}

// A fix's error, named by its style and id; as all() otherwise.
void Error::fix_error(const char *file, int line, Fix *fix, const char *style, const char *str)
{
  {
    char text[1024];
    if (says_something(str))
      std::snprintf(text, sizeof text, "Fix %s (id %s): %s", style, fix->id, str);
    else
      std::snprintf(text, sizeof text, "Illegal fix %s (id %s) command", style, fix->id);
    ohmdem::note_error(text);
  }
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    for (FILE *f : {screen, logfile}) {
      if (!f) continue;
      if (says_something(str))
        std::fprintf(f, "ERROR: Fix %s (id %s): %s (%s:%d)\n", style, fix->id, str, file, line);
      else
        std::fprintf(f, "ERROR: Illegal fix %s (id %s) command (%s:%d)\n", style, fix->id, file,
                     line);
    }
  }
  end_world(lmp, str);
}

void Error::fix_error(const char *file, int line, Fix *fix, const char *str)
{
  fix_error(file, line, fix, fix->style, str);
}

// A compute's error, named by its style and id; as all() otherwise.
void Error::compute_error(const char *file, int line, Compute *compute, const char *str)
{
  {
    char text[1024];
    if (says_something(str))
      std::snprintf(text, sizeof text, "Compute %s (id %s): %s", compute->style, compute->id, str);
    else
      std::snprintf(text, sizeof text, "Illegal compute %s (id %s) command", compute->style,
                    compute->id);
    ohmdem::note_error(text);
  }
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    for (FILE *f : {screen, logfile}) {
      if (!f) continue;
      if (says_something(str))
        std::fprintf(f, "ERROR: Compute %s (id %s): %s (%s:%d)\n", compute->style, compute->id, str,
                     file, line);
      else
        std::fprintf(f, "ERROR: Illegal compute %s (id %s) command (%s:%d)\n", compute->style,
                     compute->id, file, line);
    }
  }
  end_world(lmp, str);
}
