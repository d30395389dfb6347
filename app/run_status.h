// SPDX-License-Identifier: GPL-2.0-or-later
// How a run ended, recorded where its outputs are (doc/run_status.md).
#ifndef OHMDEM_RUN_STATUS_H
#define OHMDEM_RUN_STATUS_H

namespace LAMMPS_NS {
class LAMMPS;
}

namespace ohmdem {

enum class RunEnd { Finished, Interrupted, Failed };

// Exit status of the executable for each end: 0, 3 (interrupted by SIGINT/SIGTERM), 1 (an
// error stopped the run, as LIGGGHTS' own exit).
int exit_status(RunEnd end);

// A run that did not finish: rewrites the end of ${out}/run.json, which the deck writes with
// `"time_reached": T0, "status": "running"}` before its run (and again with "finished" after it),
// as `"time_reached": T, "status": "interrupted" | "failed"}`, T the simulated time reached (fix
// signal/table's time when the deck has one, else step x dt). On an interruption, the restart
// file LIGGGHTS forced into the working folder moves into ${out}. Rank 0 of the world only;
// nothing when the deck defines no `out` or its run.json is not "running".
void record_unfinished_run(LAMMPS_NS::LAMMPS *lmp, RunEnd end);

// The message of the error that ends the run (its text, without the source location), for
// run.json's "error"; said by LIGGGHTS' error exits (app/liggghts_errors.cpp).
void note_error(const char *message);

// Where the world's log file is, on every process (LIGGGHTS opens it on process 0 only):
// learnt at the start and after each `log` command (collective over the world).
void learn_log_path(LAMMPS_NS::LAMMPS *lmp);
// Appends LINE to the world's log from a process that does not hold it open (an error raised
// on one process); nothing when there is no log.
void append_to_log(const char *line);

// A run stopped by an error on this process alone (MPI_Abort): run.json is rewritten from here,
// whichever process this is (process 0 may be waiting in a collective).
void record_abort(LAMMPS_NS::LAMMPS *lmp);

// Arms the exit() hook that records "failed" (LIGGGHTS' error->all ends the process with
// exit(1)) for lmp; disarm before lmp goes away. Collective over lmp's world.
void record_failure_at_exit(LAMMPS_NS::LAMMPS *lmp);
void disarm_failure_at_exit();

}  // namespace ohmdem

#endif
