// SPDX-License-Identifier: GPL-2.0-or-later
// The forms of a deck's variables (src_fix/lib/writers/variable_forms.*): what each accepts,
// and a message that says what was expected and what was given.
#include <gtest/gtest.h>

#include <stdexcept>

#include "writers/variable_forms.h"

using ohmdem::form_mismatch;
using ohmdem::VariableKind;

namespace {
VariableKind kinds(const std::string &name)
{
  return name == "profile" ? VariableKind::Equal
         : name == "text"  ? VariableKind::Other
                           : VariableKind::None;
}
}  // namespace

TEST(VariableForms, Numbers)
{
  for (const char *ok : {"13", "-1.5e-3", ".5", "+2", "1e6"})
    EXPECT_EQ(form_mismatch("number", ok, kinds), "") << ok;
  EXPECT_EQ(form_mismatch("number", "many", kinds), "expected a number, got 'many'");
  for (const char *bad : {"", "2;touch x", "1 2", "inf", "nan", "1e999", "0x10"})
    EXPECT_NE(form_mismatch("number", bad, kinds), "") << bad;
}

TEST(VariableForms, ChoicesAndEqualStyleVariables)
{
  EXPECT_EQ(form_mismatch("new|restart", "restart", kinds), "");
  EXPECT_EQ(form_mismatch("new|restart", "resume", kinds), "expected new or restart, got 'resume'");
  EXPECT_EQ(form_mismatch("number|v_equal", "v_profile", kinds), "");
  EXPECT_EQ(form_mismatch("number|v_equal", "v_nosuch", kinds),
            "expected a number or v_NAME of an equal-style variable, got 'v_nosuch' (no "
            "variable 'nosuch')");
  EXPECT_NE(form_mismatch("number|v_equal", "v_text", kinds).find("is not equal-style"),
            std::string::npos);
  EXPECT_EQ(form_mismatch("number|lubricant", "lubricant", kinds), "");
}

TEST(VariableForms, PathsAndWords)
{
  EXPECT_EQ(form_mismatch("path", "./x\",\"omega_inner\":5000,\"y\":\"/oil", kinds), "");
  EXPECT_EQ(form_mismatch("folder", "results/run_1", kinds), "");
  for (const char *bad : {"a b", "x\ntouch y", "'quoted'", "\"q", ""})
    EXPECT_NE(form_mismatch("path", bad, kinds), "") << bad;
  EXPECT_NE(form_mismatch("folder", "out/network.*", kinds), "");
  EXPECT_NE(form_mismatch("folder", "out/r.%", kinds), "");
  EXPECT_NE(form_mismatch("word", "5e-6 arc 0.05", kinds), "");
  EXPECT_THROW(form_mismatch("num ber", "1", kinds), std::invalid_argument);
  EXPECT_FALSE(ohmdem::valid_form("a||b"));
}
