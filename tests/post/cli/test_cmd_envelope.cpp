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

#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::make_run_dir;
using test::run;
using test::shell;

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
