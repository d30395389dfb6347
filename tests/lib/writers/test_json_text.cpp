// SPDX-License-Identifier: GPL-2.0-or-later
// The JSON writer of run.json (src_fix/lib/writers/json_text.*): strings escaped so that a
// value can never close its quotes and add a key, numbers in JSON's form, keys once; the
// flat reader gives back what the writer wrote.
#include <gtest/gtest.h>

#include "writers/json_text.h"

namespace json = ohmdem::json;

TEST(JsonText, QuotesAndBackslashesEscaped)
{
  EXPECT_EQ(json::quote("VG68"), "\"VG68\"");
  EXPECT_EQ(json::quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json::quote("x\ny\tz\r\x01\x7f"), "\"x\\ny\\tz\\r\\u0001\\u007f\"");
  EXPECT_EQ(json::quote("caf\xc3\xa9 \xe2\x82\xac"), "\"caf\xc3\xa9 \xe2\x82\xac\"");
}

TEST(JsonText, NotUtf8IsRefused)
{
  EXPECT_THROW(json::quote("a\xff"), json::JsonError);
  EXPECT_THROW(json::quote("\xc0\xaf"), json::JsonError);      // overlong '/'
  EXPECT_THROW(json::quote("\xed\xa0\x80"), json::JsonError);  // a surrogate
  EXPECT_THROW(json::quote("\xe2\x82"), json::JsonError);      // cut
}

// The folder name of the issue: it stays one value, and no second omega_inner appears.
TEST(JsonText, InjectedKeyStaysOneValue)
{
  json::Object o;
  o.add_number("omega_inner", "500");
  o.add_string("lubricant", "./x\",\"omega_inner\":5000,\"y\":\"/oil");
  const auto back = json::read_flat(o.text());
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].second, "500");
  EXPECT_EQ(json::unquote(back[1].second), "./x\",\"omega_inner\":5000,\"y\":\"/oil");
}

TEST(JsonText, NumbersKeepTheirTextOrGetAJsonForm)
{
  EXPECT_EQ(json::number("0.02"), "0.02");
  EXPECT_EQ(json::number("5e-06"), "5e-06");
  EXPECT_EQ(json::number("-1.5E+3"), "-1.5E+3");
  EXPECT_EQ(json::number(".5"), "0.5");
  EXPECT_EQ(json::number("+2"), "2");
  EXPECT_EQ(json::number("1."), "1");
  EXPECT_EQ(json::number("007"), "7");
  for (const char *bad : {"", " 1", "1 ", "inf", "nan", "1e400", "12abc", "0x10", "1,5", "-"})
    EXPECT_THROW(json::number(bad), json::JsonError) << bad;
}

TEST(JsonText, ObjectLayoutAndDuplicateKeys)
{
  json::Object o;
  o.add_string("a", "x");
  o.add_number("b", "1");
  EXPECT_EQ(o.text(), "{\"a\": \"x\", \"b\": 1}");
  EXPECT_THROW(o.add_number("a", "2"), json::JsonError);
  try {
    o.add_number("c", "abc");
    FAIL();
  } catch (const json::JsonError &e) {
    EXPECT_NE(std::string(e.what()).find("c: 'abc' is not a finite number"), std::string::npos);
  }
}

TEST(JsonText, ReaderRefusesDuplicatesAndNesting)
{
  EXPECT_THROW(json::read_flat("{\"a\": 1, \"a\": 2}"), json::JsonError);
  EXPECT_THROW(json::read_flat("{\"a\": {\"b\": 1}}"), json::JsonError);
  EXPECT_THROW(json::read_flat("{\"a\": 1} x"), json::JsonError);
  const auto v =
      json::read_flat(" {\"a\": 1, \"b\": \"q\\\"\\u00e9\\ud83d\\ude00\", \"c\": null}\n");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(json::unquote(v[1].second), "q\"\xc3\xa9\xf0\x9f\x98\x80");
}
