// SPDX-License-Identifier: GPL-2.0-or-later
// MATLAB .mat input (libmatio): the fixtures of tests/post/make_mat_fixtures.py (scipy.io.savemat)
// and the measured CWRU records found beside the repository (if present), whose .mat and .txt
// give the same statistics.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "core/error.h"
#include "dsp/stats.h"
#include "io/load_signal.h"
#include "io/read_mat.h"
#include "temp_dir.h"
#include "test_constants.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using ohmdem::test::kPi;

std::string mat(const std::string &name)
{
  return test::data("mat/" + name);
}

std::string error_of(const std::function<void()> &f)
{
  try {
    f();
  } catch (const Error &e) {
    return e.what();
  }
  return "(no error)";
}

double expected_x(int k)
{
  return 0.5 * std::sin(2 * kPi * 50 * k / 1000.0) + 0.01 * k;
}

TEST(Mat, ReadsDoubleSingleAndIntegerVectors)
{
  for (const char *file : {"good.mat", "good_z.mat", "good_v4.mat"}) {
    const auto x = read_mat_vector(mat(file), "x");
    ASSERT_EQ(x.size(), 300u) << file;
    // (numpy's and glibc's sin may differ in the last bit)
    for (int k = 0; k < 300; ++k) ASSERT_NEAR(x[k], expected_x(k), 1e-14) << file << " " << k;
    EXPECT_EQ(read_mat_scalar(mat(file), "fs"), 1000.0);
  }
  const auto y = read_mat_vector(mat("good.mat"), "y");  // single
  for (int k = 0; k < 300; ++k) {
    ASSERT_NEAR(y[k], 2 * expected_x(k), 4e-7 * std::fabs(2 * expected_x(k)));
    ASSERT_EQ(y[k], static_cast<double>(static_cast<float>(y[k])));  // float values
  }
  const auto n16 = read_mat_vector(mat("good.mat"), "n16");  // int16
  for (int k = 0; k < 300; ++k) ASSERT_NEAR(n16[k], 1000 * expected_x(k), 0.5 + 1e-9);
  for (int k = 0; k < 300; ++k) ASSERT_EQ(n16[k], std::nearbyint(n16[k]));
  EXPECT_EQ(read_mat_scalar(mat("good.mat"), "RPM"), 1797.0);  // uint16
}

TEST(Mat, LoadSignalDetectsMatAndTakesTheRateFromAVariable)
{
  InputOptions o;
  o.files = {mat("good.mat")};
  o.column = "x";
  o.rate_variable = "fs";
  const Signal s = load_signal(o, {});
  EXPECT_EQ(s.rate, 1000.0);
  EXPECT_EQ(s.size(), 300u);
  EXPECT_NEAR(s.x[7], expected_x(7), 1e-14);
  EXPECT_EQ(s.name, "x");
  // without a rate: an error saying how to give it
  o.rate_variable.clear();
  EXPECT_NE(error_of([&] { load_signal(o, {}); }).find("pass rate HZ"), std::string::npos);
  // --from/--to apply as for every input
  o.rate = 1000;
  o.from = 0.1;
  o.to = 0.2;
  EXPECT_EQ(load_signal(o, {}).size(), 101u);
}

TEST(Mat, ReadsHdf5BasedV73)
{
  // Debian's libmatio is built with HDF5: write a v7.3 file with it and read it back
  const std::string path = ohmdem::test::temp_dir().string() + "/v73.mat";
  std::remove(path.c_str());
  mat_t *f = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT73);
  if (!f) GTEST_SKIP() << "this libmatio cannot write MAT v7.3 (built without HDF5)";
  double v[5] = {1.5, -2, 3.25, 4, 5e-3};
  size_t dims[2] = {5, 1};
  matvar_t *var = Mat_VarCreate("sig", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, v, 0);
  ASSERT_NE(var, nullptr);
  ASSERT_EQ(Mat_VarWrite(f, var, MAT_COMPRESSION_NONE), 0);
  Mat_VarFree(var);
  Mat_Close(f);
  EXPECT_TRUE(has_mat_header(path));
  const auto x = read_mat_vector(path, "sig");
  ASSERT_EQ(x.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(x[i], v[i]);
}

// A copy of a fixture cut to `keep` bytes, or with `flip` bytes from `at` inverted.
std::string damaged(const std::string &name, const std::string &as, std::size_t keep,
                    std::size_t at = 0, std::size_t flip = 0)
{
  std::string b = test::slurp(mat(name));
  for (std::size_t k = at; k < at + flip && k < b.size(); ++k) b[k] = static_cast<char>(~b[k]);
  return test::write_temp(as, b.substr(0, keep));
}

// scipy.io.loadmat refuses each of these (tests/post/damaged_mat.py checks it); libmatio alone
// reads the missing half of a cut file as zeros and a damaged compressed variable as garbage.
TEST(Mat, DamagedFilesAreRefused)
{
  const std::size_t plain = test::slurp(mat("good.mat")).size();
  const std::size_t z = test::slurp(mat("good_z.mat")).size();
  const std::size_t v4 = test::slurp(mat("good_v4.mat")).size();
  struct Case {
    std::string path, expected;
  };
  const Case cases[] = {
      {damaged("good.mat", "cut_half.mat", plain / 2),
       "variable 'x' at byte 128 holds 2448 bytes, only 2172 follow its tag (a cut or truncated"},
      {damaged("good.mat", "cut_tag.mat", 132),
       "the element at byte 128 is cut: 4 of its 8-byte tag"},
      {damaged("good_z.mat", "cut_z.mat", z / 2),
       "the element at byte 128 holds 2154 bytes, only 1928 follow its tag"},
      {damaged("good_z.mat", "flipped_z.mat", z, 300, 40),
       "the compressed element at byte 128 does not decompress (zlib: incorrect data check)"},
      {damaged("good_v4.mat", "cut_v4.mat", v4 - 100),
       "variable 'x' at byte 0 (300x1) needs 2422 bytes, only 2353 are left"},
  };
  for (const Case &c : cases) {
    const std::string e = error_of([&] { read_mat_vector(c.path, "x"); });
    EXPECT_NE(e.find(c.path + ": damaged MAT file: " + c.expected), std::string::npos) << e;
    EXPECT_NE(error_of([&] { mat_variables(c.path); }).find("damaged MAT file"), std::string::npos);
  }
  // a variable's data that do not hold its dimensions (a 300-element x whose data say 299)
  std::string b = test::slurp(mat("good.mat"));
  const std::size_t data_tag = 128 + 8 + 16 + 16 + 8;      // flags, dims (2), name 'x' (small)
  ASSERT_EQ(static_cast<unsigned char>(b[data_tag]), 9u);  // miDOUBLE
  b[data_tag + 4] = static_cast<char>(static_cast<unsigned char>(b[data_tag + 4]) - 8);
  const std::string short_data = test::write_temp("short_data.mat", b);
  EXPECT_NE(error_of([&] {
              read_mat_vector(short_data, "x");
            }).find("variable 'x' (1x300) holds 2392 data bytes, its 300 elements need 2400"),
            std::string::npos)
      << error_of([&] { read_mat_vector(short_data, "x"); });
  // the untouched fixtures (plain, compressed, v4; structs, cells, chars) still read
  for (const char *f : {"good.mat", "good_z.mat", "good_v4.mat"})
    EXPECT_EQ(read_mat_vector(mat(f), "x").size(), 300u) << f;
  EXPECT_EQ(mat_variables(mat("bad.mat")).size(), 8u);
}

TEST(Mat, ClearErrors)
{
  const std::string bad = mat("bad.mat");
  const std::string missing = error_of([&] { read_mat_vector(bad, "DE_time"); });
  EXPECT_NE(missing.find("'DE_time' not found"), std::string::npos) << missing;
  EXPECT_NE(missing.find("m (3x4 double)"), std::string::npos) << missing;  // lists variables
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "c"); }).find("complex double"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "m"); }).find("3x4 double matrix"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "s"); }).find("struct"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "cell"); }).find("cell"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "name"); }).find("char"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "e"); }).find("empty"), std::string::npos);
  EXPECT_NE(error_of([&] { read_mat_vector(bad, "nan"); }).find("element 5 is a non-finite"),
            std::string::npos);
  const std::string notmat = error_of([&] { read_mat_vector(mat("not_mat.mat"), "x"); });
  EXPECT_NE(notmat.find("not a MATLAB MAT-file"), std::string::npos) << notmat;
  EXPECT_NE(error_of([&] { mat_variables(mat("missing.mat")); }).find("cannot open"),
            std::string::npos);
  // the only vector is the default signal; several vectors need --variable
  EXPECT_EQ(default_mat_variable(mat("good_v4.mat")), "x");
  EXPECT_NE(error_of([&] {
              default_mat_variable(mat("good.mat"));
            }).find("choose the signal with variable NAME"),
            std::string::npos);
}

}  // namespace
}  // namespace ohmdem::post
