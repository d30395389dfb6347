// SPDX-License-Identifier: GPL-2.0-or-later
#include "cli_run.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <memory>

#include "bearing/bearing.h"
#include "synth.h"
#include "temp_dir.h"

namespace ohmdem::post::test {

// Runs a shell command line (stdout and stderr together).
CliRun shell(const std::string &command)
{
  CliRun r;
  std::unique_ptr<FILE, int (*)(FILE *)> p(popen((command + " 2>&1").c_str(), "r"), pclose);
  if (!p) return r;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p.get())) r.out.append(buf, n);
  const int st = pclose(p.release());
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

CliRun run(const std::string &args)
{
  return shell(std::string(OHMDEM_POST_EXE) + " " + args);
}

// A run directory as our decks write it: signal.txt (R at 1 MHz) and run.json.
std::string make_run_dir(const std::string &name, const std::string &kind)
{
  const std::string dir = ohmdem::test::temp_dir().string() + "/" + name;
  ::mkdir(dir.c_str(), 0755);
  DefectSpec spec;
  spec.kind = kind;
  spec.snr_db = 20;
  spec.duration = 0.15;
  const auto sig = defect_signal(bearing_preset("machado2014"), spec);
  std::ofstream out(dir + "/signal.txt");
  out << "# time omega_cage fn_inner_mean fn_outer_mean n_contacts_race R n_masked\n";
  char buf[256];
  // a sliding phase of 5 ms first, with a different level, that the diagnosis must skip
  for (std::size_t i = 0; i < 5000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 150 24 24 26 %.9g 0\n", i * 1e-6, 1.2 + 1e-4 * (i % 97));
    out << buf;
  }
  for (std::size_t i = 0; i < sig.signal.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.9g 198.05 24.6 24.6 26 %.9g 0\n", (i + 5000) * 1e-6,
                  sig.signal.x[i]);
    out << buf;
  }
  std::ofstream(dir + "/run.json")
      << "{\"bearing\":\"6208\",\"omega_inner\":500.0,\"nb\":13,\"db\":0.0126,\"dp\":0.0606,"
         "\"contact_angle\":0,\"dt\":1e-6,\"defect\":\""
      << kind << "\",\"size_deg\":1.0,\"load\":\"force\",\"F\":320,\"t_sliding_end\":0.005}\n";
  return dir;
}

}  // namespace ohmdem::post::test
