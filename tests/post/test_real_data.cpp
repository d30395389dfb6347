// SPDX-License-Identifier: GPL-2.0-or-later
// Measured data: runs `ohmdem-post diagnose` on every measured CWRU record found beside the
// repository (if present) with the rate, speed and bearing its README gives, and prints what it
// finds. Nothing is asserted per file: the README does not say which record has which defect.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <memory>

#include "cwru.h"
#include "io/json.h"

namespace ohmdem::post {
namespace {

TEST(RealData, DiagnoseEveryMeasuredRecordAndPrint)
{
  const std::string dir = test::cwru_dir();
  if (!test::cwru_present()) GTEST_SKIP() << dir << " not found";
  const test::CwruReadme rd = test::parse_cwru_readme(dir + "/README.md");
  ASSERT_FALSE(rd.records.empty());
  ASSERT_FALSE(rd.nb.empty() || rd.db_mm.empty() || rd.dp_mm.empty());
  const std::string geometry = "--nb " + rd.nb + " --db " +
                               std::to_string(std::stod(rd.db_mm) / 1000) + " --dp " +
                               std::to_string(std::stod(rd.dp_mm) / 1000) + " --beta " +
                               (rd.angle_deg.empty() ? "0" : rd.angle_deg);
  std::printf("\n[ real data  ] %s\n[ real data  ] geometry from README: %s\n", dir.c_str(),
              geometry.c_str());
  std::printf("[ real data  ] %-6s %6s %-7s %6s %10s %10s  %-8s %s\n", "record", "rpm", "defect",
              "score", "f_Hz", "kin_Hz", "spectrum", "family scores (inner outer ball cage)");
  for (const test::CwruRecord &rec : rd.records) {
    const std::string file = dir + "/" + rec.name + ".txt";
    char rate[32], rpm[32];
    std::snprintf(rate, sizeof rate, "%g", rec.rate);
    std::snprintf(rpm, sizeof rpm, "%g", rec.rpm);
    const std::string cmd = std::string(OHMDEM_POST_EXE) + " diagnose " + file + " --rate " + rate +
                            " --rpm " + rpm + " " + geometry + " --format json 2>&1";
    std::unique_ptr<FILE, int (*)(FILE *)> p(popen(cmd.c_str(), "r"), pclose);
    ASSERT_TRUE(p);
    std::string out;
    char buf[4096];
    while (std::size_t n = fread(buf, 1, sizeof buf, p.get())) out.append(buf, n);
    Json j;
    ASSERT_NO_THROW(j = Json::parse(out, rec.name)) << out;
    const Json *fam = j.find("families");
    ASSERT_TRUE(fam);
    std::string spec = "-";
    if (const Json *f = fam->find(j.find("defect")->string())) spec = f->find("spectrum")->string();
    std::printf(
        "[ real data  ] %-6s %6.0f %-7s %6.2f %10.3f %10.3f  %-8s %.2f %.2f %.2f %.2f\n",
        rec.name.c_str(), rec.rpm, j.find("defect")->string().c_str(), j.find("score")->number(),
        j.find("frequency_hz")->is_null() ? 0.0 : j.find("frequency_hz")->number(),
        j.find("kinematic_hz")->is_null() ? 0.0 : j.find("kinematic_hz")->number(), spec.c_str(),
        fam->find("inner")->find("score")->number(), fam->find("outer")->find("score")->number(),
        fam->find("ball")->find("score")->number(), fam->find("cage")->find("score")->number());
  }
}

}  // namespace
}  // namespace ohmdem::post
