// SPDX-License-Identifier: GPL-2.0-or-later
// How a run ended, recorded in ${out}/run.json; standard streams flushed before an abort.
#include "run_status.h"

#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"
#include "variable.h"
#include "writers/json_text.h"
#include "writers/run_folder.h"

namespace fs = std::filesystem;
namespace json = ohmdem::json;

namespace ohmdem {
namespace {

LAMMPS_NS::LAMMPS *g_lmp = nullptr;  // for the exit() hook
int g_rank = -1;         // rank in the world, read while MPI runs (error->all finalizes it first)
std::string g_error;     // the message of the error that ends the run
std::string g_log_path;  // the world's log file ("" without one)
long g_root_pid = 0;     // process 0 of the world: the lock of the run's folder names it
std::string g_root_host;

std::string host_name()
{
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0) return "unknown";
  return host;
}

// The error as a JSON string; bytes that are not UTF-8 become '?' (a message, not a path).
std::string error_json(const std::string &message)
{
  try {
    return json::quote(message);
  } catch (const json::JsonError &) {
    std::string ascii = message;
    for (char &c : ascii)
      if (static_cast<unsigned char>(c) >= 0x80) c = '?';
    return json::quote(ascii);
  }
}

const char *status_name(RunEnd end)
{
  switch (end) {
    case RunEnd::Finished:
      return "finished";
    case RunEnd::Interrupted:
      return "interrupted";
    case RunEnd::Failed:
      return "failed";
  }
  return "failed";
}

std::string read_all(const fs::path &p)
{
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The simulated time reached: fix signal/table keeps it across dt changes and restarts; else
// the step count times the current step.
double time_reached(LAMMPS_NS::LAMMPS *lmp)
{
  if (lmp->modify) {
    LAMMPS_NS::Fix *f = lmp->modify->find_fix_style("signal/table", 0);
    if (f) return f->compute_scalar();
  }
  if (lmp->update) return static_cast<double>(lmp->update->ntimestep) * lmp->update->dt;
  return std::nan("");
}

void move_forced_restart(LAMMPS_NS::LAMMPS *lmp, const fs::path &out)
{
  if (!lmp->update) return;
  const fs::path name =
      "restart_forced_liggghts_" + std::to_string(lmp->update->ntimestep) + ".data";
  std::error_code ec;
  if (!fs::is_regular_file(name, ec) || fs::equivalent(name, out / name, ec)) return;
  fs::rename(name, out / name, ec);
  if (ec) {  // another file system: copy, then remove
    ec.clear();
    fs::copy_file(name, out / name, fs::copy_options::overwrite_existing, ec);
    if (!ec) fs::remove(name, ec);
  }
  if (!ec && lmp->screen)
    std::fprintf(lmp->screen, "ohmdem: forced restart file moved to %s\n",
                 (out / name).string().c_str());
}

}  // namespace

int exit_status(RunEnd end)
{
  switch (end) {
    case RunEnd::Finished:
      return 0;
    case RunEnd::Interrupted:
      return 3;
    case RunEnd::Failed:
      return 1;
  }
  return 1;
}

namespace {

void record(LAMMPS_NS::LAMMPS *lmp, RunEnd end, bool this_rank)
{
  if (!lmp || !lmp->input || !lmp->input->variable || end == RunEnd::Finished) return;
  // exit() skips the fixes' end of run: the rows fix signal/table still buffers would be lost
  if (end == RunEnd::Failed && lmp->modify)
    for (int i = 0; i < lmp->modify->nfix; ++i)
      if (std::string(lmp->modify->fix[i]->style) == "signal/table")
        lmp->modify->fix[i]->post_run();
  if (g_rank < 0) MPI_Comm_rank(lmp->world, &g_rank);
  if (g_rank != 0 && !this_rank) return;
  char name[] = "out";
  const char *out = lmp->input->variable->retrieve(name);
  if (!out) return;
  const fs::path dir(out), meta = dir / "run.json";
  // the lock names process 0 of the world
  const long pid = g_root_pid ? g_root_pid : static_cast<long>(::getpid());
  if (locked_by_another(out, pid, g_root_host.empty() ? host_name() : g_root_host))
    return;  // another run's folder
  std::error_code ec;
  if (!fs::is_regular_file(meta, ec)) return;
  if (end == RunEnd::Interrupted) move_forced_restart(lmp, dir);
  std::string text = read_all(meta);
  const std::size_t status = text.rfind("\"status\": \"running\"");
  const std::size_t reached = text.rfind("\"time_reached\": ", status);
  if (status == std::string::npos || reached == std::string::npos) return;
  const double t = time_reached(lmp);
  char when[40] = "null";
  if (std::isfinite(t)) *std::to_chars(when, when + sizeof when - 1, t).ptr = '\0';
  // The error that stopped the run, as the log says it (doc/run_status.md).
  const std::string error =
      end == RunEnd::Failed && !g_error.empty() ? ", \"error\": " + error_json(g_error) : "";
  const std::string tail = std::string("\"time_reached\": ") + when + ", \"status\": \"" +
                           status_name(end) + "\"" + error + "}\n";
  const std::string short_tail =
      std::string("\"time_reached\": ") + when + ", \"status\": \"" + status_name(end) + "\"}\n";
  text.replace(reached, std::string::npos, tail);
  const fs::path tmp = dir / ("run.json.tmp" + std::to_string(::getpid()));
  {
    std::ofstream o(tmp, std::ios::binary | std::ios::trunc);
    o << text;
    o.close();
    if (o) {
      fs::rename(tmp, meta, ec);
      return;
    }
  }
  // A full disk has no room for a second file: rewrite the tail in place (the blocks of the
  // file are already there; "failed" is shorter than "running"; the error's text may not fit
  // in them, then the status alone).
  fs::remove(tmp, ec);
  for (const std::string &t : {tail, short_tail}) {
    std::FILE *f = std::fopen(meta.c_str(), "r+b");
    if (!f) return;
    const bool ok = std::fseek(f, static_cast<long>(reached), SEEK_SET) == 0 &&
                    std::fputs(t.c_str(), f) >= 0 && std::fflush(f) == 0;
    std::fclose(f);
    if (ok) {
      (void)::truncate(meta.c_str(), static_cast<off_t>(reached + t.size()));
      return;
    }
  }
}

}  // namespace

void record_unfinished_run(LAMMPS_NS::LAMMPS *lmp, RunEnd end)
{
  record(lmp, end, false);
}

void record_abort(LAMMPS_NS::LAMMPS *lmp)
{
  record(lmp, RunEnd::Failed, true);
}

void note_error(const char *message)
{
  if (message && g_error.empty()) g_error = message;  // the first one is the cause
}

void learn_log_path(LAMMPS_NS::LAMMPS *lmp)
{
  int me = 0;
  MPI_Comm_rank(lmp->world, &me);
  std::string path;
  if (me == 0 && lmp->logfile) {
    char link[64], target[PATH_MAX];
    std::snprintf(link, sizeof link, "/proc/self/fd/%d", ::fileno(lmp->logfile));
    const ssize_t n = ::readlink(link, target, sizeof target - 1);
    if (n > 0) path.assign(target, static_cast<std::size_t>(n));
  }
  int length = static_cast<int>(path.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, lmp->world);
  path.resize(static_cast<std::size_t>(length));
  MPI_Bcast(path.data(), length, MPI_CHAR, 0, lmp->world);
  g_log_path = path;
}

void append_to_log(const char *line)
{
  if (g_log_path.empty() || !line) return;
  const int fd = ::open(g_log_path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) return;
  const std::size_t n = std::strlen(line);
  (void)!::write(fd, line, n);
  ::close(fd);
}

void record_failure_at_exit(LAMMPS_NS::LAMMPS *lmp)
{
  static bool registered = false;
  g_lmp = lmp;
  MPI_Comm_rank(lmp->world, &g_rank);
  // Process 0's pid and host, which its lock of the run's folder names, on every process.
  long pid = static_cast<long>(::getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, lmp->world);
  g_root_pid = pid;
  std::string host = host_name();
  int length = static_cast<int>(host.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, lmp->world);
  host.resize(static_cast<std::size_t>(length));
  MPI_Bcast(host.data(), length, MPI_CHAR, 0, lmp->world);
  g_root_host = host;
  if (registered) return;
  registered = true;
  std::atexit([] {
    LAMMPS_NS::LAMMPS *lmp = g_lmp;
    g_lmp = nullptr;
    record_unfinished_run(lmp, RunEnd::Failed);
  });
}

void disarm_failure_at_exit()
{
  g_lmp = nullptr;
}

}  // namespace ohmdem

// Errors raised on one process (LIGGGHTS' error->one) write to the screen stream and call
// MPI_Abort, which ends the processes without flushing: a message sent to a file (stdout
// redirected, a partition's screen file) would be lost. The MPI profiling interface lets the
// executable flush every stream first.
extern "C" int MPI_Abort(MPI_Comm comm, int errorcode)
{
  // An error on one process (a failed write of fix signal/table: a full disk) ends here, not
  // in exit(): record the failure in run.json first, where it can still be written.
  if (LAMMPS_NS::LAMMPS *lmp = ohmdem::g_lmp) {
    ohmdem::g_lmp = nullptr;
    ohmdem::record_abort(lmp);
  }
  std::fflush(nullptr);
  return PMPI_Abort(comm, errorcode);
}
