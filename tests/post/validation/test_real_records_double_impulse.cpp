// SPDX-License-Identifier: GPL-2.0-or-later
// `diagnose --size-method double-impulse` on the measured CWRU records beside the repository
// (skipped when absent): a size with its interval, or the reason there is none.
#include <gtest/gtest.h>

#include <string>

#include "cli_run.h"
#include "cwru.h"
#include "io/json.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;

// The command's JSON, its status checked.
Json json_of(const CliRun &r, const std::string &what)
{
  EXPECT_EQ(r.status, 0) << r.out;
  return Json::parse(r.out.substr(r.out.find('{')), what);
}

TEST(DiagnoseDoubleImpulse, RealRecordsGiveASizeWithIntervalOrSayWhyNot)
{
  // The CWRU records' pits are 0.1778, 0.3556 or 0.5334 mm: 101, 202, 303 us at the 6205's
  // rolling speed at 1797 rpm (1.76 m/s), 1.2, 2.4, 3.6 samples at 12 kHz (doc/ohmdem-post.md).
  const std::string dir = ohmdem::test::cwru_dir();
  if (!ohmdem::test::cwru_present()) GTEST_SKIP() << dir << " not found";
  for (const char *rec : {"sig01", "sig02", "sig07"}) {
    const Json j = json_of(run("diagnose --format json " + dir + "/" + rec +
                               ".mat --variable DE_time --rate 12000 --rpm-variable RPM "
                               "--bearing 6205 --size-method double-impulse"),
                           rec);
    const std::string method = j.find("size_method")->string();
    const Json *iv = j.find("size_interval_deg");
    if (iv && !iv->is_null()) {
      EXPECT_NE(method.find("double impulse"), std::string::npos) << rec;
      EXPECT_LE((*iv)[0].number(), j.find("size_deg")->number()) << rec;
      EXPECT_GE((*iv)[1].number(), j.find("size_deg")->number()) << rec;
    } else {
      EXPECT_NE(method.find("not determined"), std::string::npos) << rec << ": " << method;
    }
    EXPECT_EQ(j.find("position_reference")->is_null(), true) << rec;
  }
}

}  // namespace
}  // namespace ohmdem::post
