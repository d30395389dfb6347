// SPDX-License-Identifier: GPL-2.0-or-later
// Ranged options of the command line: a value outside its range is an error naming the option,
// the expected form and the value; inside, the value (or the default) is returned.
#include <gtest/gtest.h>

#include <climits>
#include <functional>
#include <sstream>

#include "cli/args.h"
#include "core/error.h"

namespace ohmdem::post::cli {
namespace {

Args parsed(const std::vector<std::string> &argv)
{
  Args a("test", "", "");
  a.option("--harmonics", "N", "", "5");
  a.option("--rate", "HZ", "");
  a.option("--p", "P", "", "0.001");
  a.option("--show", "WHAT", "", "peaks");
  std::ostringstream help;
  EXPECT_TRUE(a.parse(argv, help));
  return a;
}

std::string error_of(const std::function<void()> &f)
{
  try {
    f();
  } catch (const Error &e) {
    return e.what();
  }
  return "";
}

TEST(Args, IntegerInRange)
{
  EXPECT_EQ(parsed({}).integer_in("--harmonics", 5, 1, 50), 5);
  EXPECT_EQ(parsed({"--harmonics", "50"}).integer_in("--harmonics", 5, 1, 50), 50);
  EXPECT_EQ(error_of([] {
              parsed({"--harmonics", "51"}).integer_in("--harmonics", 5, 1, 50);
            }),
            "option --harmonics expects an integer in 1..50, got 51");
  EXPECT_EQ(error_of([] {
              parsed({"--harmonics=0"}).integer_in("--harmonics", 5, 1, LLONG_MAX, "a count");
            }),
            "option --harmonics expects a count >= 1, got 0");
  EXPECT_EQ(error_of([] {
              parsed({"--harmonics", "2.5"}).integer_in("--harmonics", 5, 1, 50);
            }),
            "option --harmonics expects an integer, got '2.5'");
}

TEST(Args, NumberInRange)
{
  EXPECT_DOUBLE_EQ(parsed({"--rate", "12000"}).number_in("--rate", 0, Range::above(0)), 12000);
  EXPECT_EQ(error_of([] {
              parsed({"--rate", "-5"}).number_in("--rate", 0, Range::above(0), "a rate", "Hz");
            }),
            "option --rate expects a rate > 0 Hz, got -5");
  EXPECT_EQ(error_of([] {
              parsed({"--p", "0.5"}).number_in("--p", 1e-3, Range::open(0, 0.5), "a probability");
            }),
            "option --p expects a probability in (0, 0.5), got 0.5");
  EXPECT_EQ(Range::at_least(0).text(), ">= 0");
  EXPECT_EQ(Range::closed(1, 2).text(), "in [1, 2]");
  EXPECT_TRUE(Range::closed(1, 2).contains(2));
  EXPECT_FALSE(Range::open(1, 2).contains(2));
}

TEST(Args, Choice)
{
  EXPECT_EQ(parsed({}).choice("--show", {"peaks", "bins"}), "peaks");
  EXPECT_EQ(error_of([] {
              parsed({"--show", "all"}).choice("--show", {"peaks", "bins"});
            }),
            "option --show expects peaks|bins, got 'all'");
}

}  // namespace
}  // namespace ohmdem::post::cli
