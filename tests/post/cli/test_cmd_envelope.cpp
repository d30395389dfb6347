// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post envelope` end to end: the kurtogram, its peaks and fault bands, and
// `frequencies` as JSON.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "io/json.h"
#include "synth.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

struct CliRun {
  int status = -1;
  std::string out;
};

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
  const std::string dir = std::string(OHMDEM_POST_TEST_TMP) + "/" + name;
  ::mkdir(dir.c_str(), 0755);
  test::DefectSpec spec;
  spec.kind = kind;
  spec.snr_db = 20;
  spec.duration = 0.15;
  const auto sig = test::defect_signal(bearing_preset("machado2014"), spec);
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

TEST(Cli, EnvelopeKurtogramAndFrequencies)
{
  const std::string dir = make_run_dir("run_env", "inner");
  const CliRun k = run("envelope " + dir +
                       "/signal.txt --from 0.005 --show kurtogram --levels 3 "
                       "--format csv");
  ASSERT_EQ(k.status, 0) << k.out;
  EXPECT_NE(k.out.find("bands,f_low_Hz,f_high_Hz,center_Hz,spectral_kurtosis"), std::string::npos);
  const CliRun e = run("envelope " + dir +
                       "/signal.txt --from 0.005 --kurtogram --peaks 1 "
                       "--fmax 2000 --format json");
  ASSERT_EQ(e.status, 0) << e.out;
  const Json j = Json::parse(e.out, "envelope output");
  EXPECT_NE((*j.find("rows"))[0].find("label")->string().find("BPFI"), std::string::npos);
  const CliRun fb = run("envelope " + dir +
                        "/signal.txt --from 0.005 --kurtogram --fault-bands "
                        "--harmonics 2 --format csv");
  ASSERT_EQ(fb.status, 0) << fb.out;
  EXPECT_NE(fb.out.find("\nlabel,f_low_Hz,f_high_Hz,center_Hz,peak_amplitude_ohm,"
                        "peak_frequency_Hz,band_power_ohm^2\n"),
            std::string::npos)
      << fb.out;
  EXPECT_NE(fb.out.find("\n2xBPFI,"), std::string::npos);
  const CliRun f = run("frequencies --bearing machado2014 --omega 500 --format json");
  ASSERT_EQ(f.status, 0);
  const Json fj = Json::parse(f.out, "frequencies output");
  EXPECT_NEAR(fj.find("bpfi_hz")->number(), 624.8, 0.05);
  EXPECT_NEAR(fj.find("two_bsf_hz")->number(), 366.18, 0.05);
}

}  // namespace
}  // namespace ohmdem::post
