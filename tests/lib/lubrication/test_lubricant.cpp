// SPDX-License-Identifier: GPL-2.0-or-later
// The lubricant catalog and its temperature laws (src_fix/lib/lubrication/lubricant.*).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "lubrication/lubricant.h"
#include "temp_dir.h"

using namespace ohmdem::lubrication;

namespace {
std::string write(const std::string &name, const std::string &text)
{
  const std::string p = ohmdem::test::temp_path(name);
  std::ofstream(p) << text;
  return p;
}
const char *kGood =
    "# comment\n"
    "variable nu40 index 68 # a\nvariable nu100 index 8.7\nvariable rho15 index 880\n"
    "variable expansion index 6.5e-4\nvariable alpha index 2.2e-8\nvariable eps_r index 2.07\n"
    "variable eps_slope index -0.0013\nvariable tref index 40\nvariable resistivity index 1e12\n";
}  // namespace

TEST(Lubricant, WaltherPassesThroughItsTwoPoints)
{
  EXPECT_NEAR(walther_viscosity(68.0, 8.7, 40.0), 68.0, 1e-9);
  EXPECT_NEAR(walther_viscosity(68.0, 8.7, 100.0), 8.7, 1e-10);
  // Between them, ASTM D341 written out here: log10 log10(nu + 0.7) linear in log10 T.
  const double t1 = 313.15, t2 = 373.15, t = 333.15;
  const double y1 = std::log10(std::log10(68.7)), y2 = std::log10(std::log10(9.4));
  const double y =
      y1 + (y2 - y1) * (std::log10(t) - std::log10(t1)) / (std::log10(t2) - std::log10(t1));
  EXPECT_NEAR(walther_viscosity(68.0, 8.7, 60.0), std::pow(10.0, std::pow(10.0, y)) - 0.7, 1e-9);
}

TEST(Lubricant, StateAtTemperature)
{
  const Lubricant lub = read_lubricant_file(write("good", kGood), "good");
  const LubricantState s = state_at(lub, 40.0);
  // eta = nu rho: 68e-6 m^2/s * 880 (1 - 6.5e-4 * 25) kg/m^3.
  EXPECT_NEAR(s.eta, 68e-6 * 880.0 * (1.0 - 6.5e-4 * 25.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.eps_r, 2.07);
  EXPECT_NEAR(state_at(lub, 80.0).eps_r, 2.07 - 0.0013 * 40.0, 1e-12);
  EXPECT_THROW(state_at(lub, 400.0), LubricantError);
}

TEST(Lubricant, CatalogFilesAllRead)
{
  for (const char *name : {"VG32", "VG68", "VG220", "PAO68"}) {
    const std::string path = lubricant_path(name, OHMDEM_TEST_LUBRICANTS);
    const Lubricant lub = read_lubricant_file(path, name);
    const LubricantState s = state_at(lub, 40.0);
    EXPECT_NEAR(s.nu * 1e6, lub.nu40, 1e-9) << name;
    EXPECT_GT(s.eta, 0.01) << name;
  }
}

TEST(Lubricant, BadInputNamesTheProblem)
{
  auto message = [](const std::string &text) {
    try {
      read_lubricant_file(write("bad", text), "bad");
    } catch (const LubricantError &e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("variable nu40 equal 68\n").find("expected 'variable NAME index VALUE"),
            std::string::npos);
  EXPECT_NE(message("variable nu40 index abc\n").find("nu40 expects a number"), std::string::npos);
  EXPECT_NE(message("variable nu40 index 68\n").find("is missing"), std::string::npos);
  std::string neg = kGood;
  neg.replace(neg.find("alpha index 2.2e-8"), 18, "alpha index -1");
  EXPECT_NE(message(neg).find("alpha must be > 0"), std::string::npos);
  try {
    lubricant_path("VG999", OHMDEM_TEST_LUBRICANTS);
    FAIL();
  } catch (const LubricantError &e) {
    EXPECT_NE(std::string(e.what()).find("known: PAO68 VG220 VG32 VG68"), std::string::npos);
  }
}
