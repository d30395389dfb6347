// SPDX-License-Identifier: GPL-2.0-or-later
// The bearing catalog reader (src_fix/lib/catalog): which names are entries, which names a user
// may give, every line of an entry in file order, errors that name the file and line, and the
// default folder ($OHMDEM_CATALOG, else the build's compiled-in source catalog).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "catalog/bearing_catalog.h"
#include "temp_dir.h"

namespace ohmdem::catalog {
namespace {

const std::string kCatalog = OHMDEM_CATALOG_DIR;
const std::string kBad = OHMDEM_CATALOG_BAD_DIR;

std::string error_of(const std::string &path)
{
  try {
    read_catalog_file(path, "x");
  } catch (const CatalogError &e) {
    return e.what();
  }
  return "";
}

void write(const std::string &path, const std::string &text)
{
  std::ofstream(path) << text;
}

TEST(CatalogReader, NamesAreTheRegularFilesWithoutADotSorted)
{
  const std::string dir = ohmdem::test::temp_path("names");
  std::filesystem::create_directories(dir + "/sub");
  write(dir + "/b2", "");
  write(dir + "/a1", "");
  write(dir + "/notes.txt", "");
  write(dir + "/.hidden", "");
  const auto names = catalog_names(dir);
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names[0], "a1");
  EXPECT_EQ(names[1], "b2");
  EXPECT_EQ(joined_names(names), "a1 b2");
  EXPECT_EQ(joined_names({}), "(none)");
}

TEST(CatalogReader, AFolderThatIsNoneIsAnError)
{
  try {
    catalog_names("/nonexistent");
    FAIL() << "no error";
  } catch (const CatalogError &e) {
    EXPECT_STREQ(e.what(), "bearing catalog '/nonexistent' is not a readable folder");
  }
}

TEST(CatalogReader, ANameIsAPlainToken)
{
  for (const char *ok : {"6208", "6205-2RS_JEM", "custom"}) EXPECT_TRUE(is_catalog_name(ok)) << ok;
  for (const char *bad :
       {"", "../6208", "a/b", ".hidden", "6208.bak", "6208;touch INJECTED", "$(touch X)",
        "`touch X`", "6208 6205", "a|b", "a&b", "a'b", "a\"b", "a\nb", "~root", "*"})
    EXPECT_FALSE(is_catalog_name(bad)) << bad;
}

TEST(CatalogReader, The6208EntryKeepsEveryLineInFileOrder)
{
  const CatalogEntry e = read_catalog_file(kCatalog + "/6208", "6208");
  EXPECT_EQ(e.name, "6208");
  EXPECT_EQ(e.path, kCatalog + "/6208");
  EXPECT_EQ(e.nb, 13);
  EXPECT_EQ(e.db, 0.0126);
  EXPECT_EQ(e.dext, 0.0732);
  EXPECT_EQ(e.dinn, 0.048);
  EXPECT_EQ(e.rc_ext, 0.00665);
  EXPECT_EQ(e.rc_inn, 0.00655);
  // the values as written (the deck defines its index variables with this text)
  const std::vector<std::pair<std::string, std::string>> want = {
      {"Nb", "13"},      {"Db", "0.0126"},     {"Dext", "0.0732"},
      {"Dinn", "0.048"}, {"Rcext", "0.00665"}, {"Rcinn", "0.00655"}};
  EXPECT_EQ(e.variables, want);
}

TEST(CatalogReader, ExtraVariablesAreKept)
{
  const std::string path = ohmdem::test::temp_path("extra");
  write(path,
        "# comment\n\nvariable Nb index 9\nvariable Db index 0.008 # src\nvariable Dext index "
        "0.047\nvariable Dinn index 0.031\nvariable Rcext index 0.0042\nvariable Rcinn index "
        "0.0041\nvariable note index 1\n");
  const CatalogEntry e = read_catalog_file(path, "extra");
  ASSERT_EQ(e.variables.size(), 7u);
  EXPECT_EQ(e.variables.back().first, "note");
}

TEST(CatalogReader, MalformedFilesNameFileAndLine)
{
  EXPECT_NE(error_of(kBad + "/syntax").find("syntax:3: expected 'variable NAME index VALUE"),
            std::string::npos);
  EXPECT_NE(error_of(kBad + "/nonnumber").find("nonnumber:2: variable Db: '8mm' is not a finite"),
            std::string::npos);
  EXPECT_NE(error_of(kBad + "/missing").find("missing 'variable Rcinn index VALUE'"),
            std::string::npos);
  EXPECT_NE(error_of(kBad + "/negative").find("Db (ball diameter, m) must be > 0, got -0.00794"),
            std::string::npos)
      << error_of(kBad + "/negative");
  EXPECT_NE(error_of(kBad + "/fractional").find("Nb (number of balls) must be an integer"),
            std::string::npos);
  EXPECT_NE(error_of(kBad + "/twice").find("twice:2: variable Nb given twice"), std::string::npos);
  EXPECT_NE(error_of("/nonexistent/6208").find("cannot open bearing catalog file"),
            std::string::npos);
}

TEST(CatalogReader, DefaultFolderIsTheEnvironmentElseTheBuildsCatalog)
{
  ::setenv("OHMDEM_CATALOG", kBad.c_str(), 1);
  EXPECT_EQ(default_catalog_dir(), kBad);
  ::setenv("OHMDEM_CATALOG", "", 1);  // empty: as if not set
  EXPECT_EQ(default_catalog_dir(), kCatalog);
  ::unsetenv("OHMDEM_CATALOG");
  // a test executable of the build tree: no installed catalog beside it
  EXPECT_EQ(installed_catalog_dir(), "");
  EXPECT_EQ(default_catalog_dir(), kCatalog);
}

}  // namespace
}  // namespace ohmdem::catalog
