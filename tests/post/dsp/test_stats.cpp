// SPDX-License-Identifier: GPL-2.0-or-later
// Indicators against numpy/scipy reference values (tests/post/make_reference.py) to 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.h"
#include "dsp/stats.h"
#include "io/json.h"
#include "io/read_table.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::reference;

const char *kKeys[] = {"peak",     "mean",  "rms",   "std",     "skewness",
                       "kurtosis", "crest", "shape", "impulse", "clearance"};

double get(const Indicators &r, const std::string &k)
{
  if (k == "peak") return r.peak;
  if (k == "mean") return r.mean;
  if (k == "rms") return r.rms;
  if (k == "std") return r.std;
  if (k == "skewness") return r.skewness;
  if (k == "kurtosis") return r.kurtosis;
  if (k == "crest") return r.crest;
  if (k == "shape") return r.shape;
  if (k == "impulse") return r.impulse;
  return r.clearance;
}

// 1e-12 relative; values that are differences near zero (a mean, a skewness) get the same
// relative tolerance on their natural scale (rms, 1) instead of on themselves.
void expect_close(double got, double want, double scale, const std::string &what)
{
  const double tol = 1e-12 * std::max(std::fabs(want), scale);
  EXPECT_NEAR(got, want, tol) << what;
}

Json load_reference()
{
  return Json::parse(test::slurp(reference("indicators.json")), "indicators.json");
}

TEST(Stats, MatchScipyReferenceTo1e12)
{
  const Json ref = load_reference();
  const Json *vectors = ref.find("vectors");
  ASSERT_TRUE(vectors && vectors->is_object());
  ASSERT_GE(vectors->size(), 6u);
  for (const auto &[name, want] : vectors->members()) {
    // read through the library's column reader, as the command line does
    const ColumnTable t = read_table(reference("sig_" + name + ".txt"));
    ASSERT_EQ(t.cols(), 1u);
    const Indicators r = indicators(t.columns[0]);
    EXPECT_EQ(static_cast<double>(r.n), want.find("n")->number()) << name;
    for (const char *k : kKeys) {
      const double scale = std::string(k) == "mean" ? r.rms : std::string(k) == "skewness" ? 1 : 0;
      expect_close(get(r, k), want.find(k)->number(), scale, name + "." + k);
    }
  }
}

TEST(Stats, CommandLineJsonMatchesReference)
{
  const Json ref = load_reference();
  for (const char *name : {"rect_train", "exponential", "gauss"}) {
    const std::string cmd = std::string(OHMDEM_POST_EXE) + " stats --rate 1000 --format json " +
                            reference(std::string("sig_") + name + ".txt");
    std::unique_ptr<FILE, int (*)(FILE *)> p(popen(cmd.c_str(), "r"), pclose);
    ASSERT_TRUE(p);
    std::string text;
    char buf[4096];
    while (std::size_t n = fread(buf, 1, sizeof buf, p.get())) text.append(buf, n);
    const Json got = Json::parse(text, "stats output");
    const Json &want = *ref.find("vectors")->find(name);
    for (const char *k : kKeys) {
      ASSERT_TRUE(got.find(k)) << k;
      const double scale = std::string(k) == "mean"       ? got.find("rms")->number()
                           : std::string(k) == "skewness" ? 1
                                                          : 0;
      expect_close(got.find(k)->number(), want.find(k)->number(), scale,
                   std::string(name) + "." + k);
    }
    EXPECT_FALSE(got.find("mean_removed")->boolean());
  }
}

TEST(Stats, ConstantSignalHasUndefinedMoments)
{
  const std::vector<double> x(100, 2.5);
  const Indicators r = indicators(x);
  EXPECT_DOUBLE_EQ(r.peak, 2.5);
  EXPECT_DOUBLE_EQ(r.mean, 2.5);
  EXPECT_DOUBLE_EQ(r.rms, 2.5);
  EXPECT_EQ(r.std, 0.0);
  EXPECT_TRUE(std::isnan(r.skewness));  // as scipy.stats.skew
  EXPECT_TRUE(std::isnan(r.kurtosis));
  EXPECT_DOUBLE_EQ(r.crest, 1.0);
}

TEST(Stats, RectangleTrainKurtosisFollowsDutyCycle)
{
  // doc/post/stats.md: an ideal rectangle train occupying a fraction d of the time
  // has kurtosis (1 - 3 d (1 - d)) / (d (1 - d)), which falls as d grows.
  for (int width : {5, 20, 100}) {
    std::vector<double> x(100000, 1.39);
    for (std::size_t i = 0; i < x.size(); i += 1000)
      for (int j = 0; j < width; ++j) x[i + static_cast<std::size_t>(j)] += 0.115;
    const double d = width / 1000.0;
    EXPECT_NEAR(indicators(x).kurtosis, (1 - 3 * d * (1 - d)) / (d * (1 - d)), 1e-9);
  }
}

TEST(Stats, NormalNoiseHasPearsonKurtosisNearThree)
{
  const ColumnTable t = read_table(reference("sig_gauss.txt"));
  const Indicators r = indicators(t.columns[0]);
  EXPECT_NEAR(r.kurtosis, 3.0, 0.4);
  EXPECT_NEAR(r.skewness, 0.0, 0.2);
}

TEST(Stats, SlidingWindowsOfConsecutiveIntegers)
{
  // 0..9, 4 samples every 3: [0,4) [3,7) [6,10), means 1.5, 4.5, 7.5; four consecutive
  // integers have the population standard deviation sqrt(1.25)
  std::vector<double> x(10);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
  const auto w = sliding_indicators(x, 4, 3, false);
  ASSERT_EQ(w.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(w[k].first, 3 * k);
    EXPECT_EQ(w[k].last, 3 * k + 4);
    EXPECT_EQ(w[k].ind.n, 4u);
    EXPECT_DOUBLE_EQ(w[k].ind.mean, 1.5 + 3 * k);
    EXPECT_NEAR(w[k].ind.std, std::sqrt(1.25), 1e-15);
  }
  const auto centred = sliding_indicators(x, 4, 3, true);
  for (const auto &c : centred) {
    EXPECT_NEAR(c.ind.mean, 0, 1e-15);
    EXPECT_NEAR(c.ind.rms, std::sqrt(1.25), 1e-15);
  }
  EXPECT_EQ(sliding_indicators(x, 10, 1, false).size(), 1u);
  EXPECT_THROW(sliding_indicators(x, 11, 1, false), Error);
  EXPECT_THROW(sliding_indicators(x, 4, 0, false), Error);
}

}  // namespace
}  // namespace ohmdem::post
