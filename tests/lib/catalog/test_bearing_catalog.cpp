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

TEST(CatalogReader, TheMachado2014EntryKeepsEveryLineInFileOrder)
{
  const CatalogEntry e = read_catalog_file(kCatalog + "/machado2014", "machado2014");
  EXPECT_EQ(e.name, "machado2014");
  EXPECT_EQ(e.path, kCatalog + "/machado2014");
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
  EXPECT_NE(error_of(kBad + "/missing").find("missing 'variable Dinn index VALUE'"),
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

TEST(CatalogReader, ANameSeveralMakersUseResolvesToItsDefaultAndListsTheOthers)
{
  const CatalogEntry e = read_entry(kCatalog, "6203");
  EXPECT_EQ(e.requested, "6203");
  EXPECT_EQ(e.name, "6203-2RS_JEM");
  EXPECT_EQ(e.path, kCatalog + "/6203-2RS_JEM");
  EXPECT_EQ(joined_names(e.others), "6203_FAG 6203_IBU-MTK 6203ZZ_NSK");
  EXPECT_EQ(read_entry(kCatalog, "6205").name, "6205-2RS_JEM");
  EXPECT_EQ(read_entry(kCatalog, "MFPT_NICE").requested, "MFPT_NICE");
  try {
    read_entry(kCatalog, "6208");
    FAIL() << "no error";
  } catch (const CatalogError &err) {
    EXPECT_EQ(
        std::string(err.what()),
        "bearing '6208' has no sourced geometry in the catalog: use machado2014 or 6208_KG (" +
            kCatalog + "/6208 says why)");
  }
  EXPECT_THROW(read_entry(kCatalog, "6999"), CatalogError);
  EXPECT_THROW(read_entry(kCatalog, "../bearings/6203"), CatalogError);
}

TEST(CatalogReader, AnEntryHoldsWhatItsSourcePublishes)
{
  const std::string dir = ohmdem::test::temp_path("published");
  std::filesystem::create_directories(dir);
  auto error = [&](const std::string &text) {
    write(dir + "/e", text);
    try {
      read_catalog_file(dir + "/e", "e");
    } catch (const CatalogError &err) {
      return std::string(err.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("variable Nb index 8\nvariable Db index 0.0076\n"), "");       // Z and Dw only
  EXPECT_EQ(error("variable BPFO index 2.62\nvariable BPFI index 4.38\n"), "");  // factors only
  EXPECT_EQ(error("variable Nb index 8\nvariable Db index 0.00675\nvariable Dpw index 0.02855\n"),
            "");
  EXPECT_NE(error("variable Nb index 8\n").find("missing 'variable Db index VALUE'"),
            std::string::npos);
  EXPECT_NE(error("# nothing\n").find("gives neither a ball set"), std::string::npos);
  EXPECT_NE(error("variable BPFO index 2.62\n").find("missing 'variable BPFI index VALUE'"),
            std::string::npos);
  EXPECT_NE(error("variable BPFO index 2.62\nvariable BPFI index 4.5\n").find("whole number"),
            std::string::npos);
  EXPECT_NE(error("variable Nb index 8\nvariable Db index 0.0067\nvariable BPFO index 2.62\n"
                  "variable BPFI index 4.38\n")
                .find("must equal Nb (8)"),
            std::string::npos);
  EXPECT_NE(error("variable Nb index 8\nvariable Db index 0.03\nvariable Dpw index 0.02\n")
                .find("must exceed Db"),
            std::string::npos);
  EXPECT_NE(error("variable Nb index 9\nvariable Db index 0.00794\nvariable Dext index 0.04698\n"
                  "variable Dinn index 0.0311\nvariable Dpw index 0.04\n")
                .find("differs from (Dext + Dinn)/2"),
            std::string::npos);
  write(dir + "/a", "alias b\n");
  write(dir + "/b", "alias c\n");
  write(dir + "/c", "variable Nb index 8\nvariable Db index 0.0076\n");
  EXPECT_THROW(read_entry(dir, "a"), CatalogError);  // an alias names an entry, not an alias
  EXPECT_EQ(read_entry(dir, "b").name, "c");
  write(dir + "/d", "alias c\nvariable Nb index 8\n");
  EXPECT_THROW(read_entry(dir, "d"), CatalogError);
}

// The deck's needs: Nb, Db and the races (Dext, Dinn) or a pitch diameter (Dpw).
TEST(CatalogReader, TheDeckRefusesAnEntryWithoutWhatTheSimulationNeedsNamingIt)
{
  const CatalogEntry nice = read_entry(kCatalog, "MFPT_NICE");
  DeckGeometry d = deck_geometry_of(&nice, {});
  EXPECT_EQ(d.error, "");
  // NiceBearing.m: Dpw 31.623 mm, Dw 5.969 mm; races Dpw +- Dw (zero clearance)
  const std::vector<std::pair<std::string, std::string>> races = {{"Dext", "0.037592"},
                                                                  {"Dinn", "0.025654"}};
  EXPECT_EQ(d.define, races);
  EXPECT_EQ(d.copies, races);
  // -var Db changes the races, and the copies keep the entry's: the run is custom
  d = deck_geometry_of(&nice, {{"Db", "0.006"}});
  EXPECT_EQ(d.define[0].second, "0.037623");
  EXPECT_EQ(d.copies, races);
  // a KG entry (Z and Dw only) names the pitch diameter and how to give it
  const CatalogEntry kg = read_entry(kCatalog, "6204_KG");
  d = deck_geometry_of(&kg, {});
  EXPECT_NE(d.error.find("bearing '6204_KG'"), std::string::npos) << d.error;
  EXPECT_NE(d.error.find("-var Dpw M (pitch diameter"), std::string::npos) << d.error;
  EXPECT_EQ(d.error.find("-var Nb"), std::string::npos) << d.error;
  d = deck_geometry_of(&kg, {{"Dpw", "0.0335"}});
  EXPECT_EQ(d.error, "");
  EXPECT_EQ(d.define[0], (std::pair<std::string, std::string>("Dext", "0.0411")));
  EXPECT_EQ(d.copies[0].second, "-1");  // a dimension from -var: custom
  // factors only: Nb (with the value its factors give), Db and the pitch diameter
  const CatalogEntry ntn = read_entry(kCatalog, "6201_NTN");
  d = deck_geometry_of(&ntn, {});
  for (const char *want :
       {"-var Nb N (number of balls; its factors give BPFO + BPFI = 7)", "-var Db M", "-var Dpw M"})
    EXPECT_NE(d.error.find(want), std::string::npos) << d.error;
  // an entry with races: nothing derived, -var Dpw replaces them
  const CatalogEntry cwru = read_entry(kCatalog, "6205-2RS_JEM");
  EXPECT_TRUE(deck_geometry_of(&cwru, {}).define.empty());
  EXPECT_EQ(deck_geometry_of(&cwru, {{"Dpw", "0.04"}}).define.size(), 2u);
  EXPECT_NE(deck_geometry_of(&cwru, {{"Dpw", "0.04"}, {"Dext", "0.05"}, {"Dinn", "0.03"}})
                .error.find("not both"),
            std::string::npos);
  EXPECT_NE(deck_geometry_of(&cwru, {{"Dpw", "abc"}}).error.find("deck variable Dpw"),
            std::string::npos);
  // custom: -var Dpw with -var Db gives the races too
  d = deck_geometry_of(nullptr, {{"Db", "0.01"}, {"Dpw", "0.05"}});
  EXPECT_EQ(d.define.size(), 2u);
  EXPECT_TRUE(d.copies.empty());
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
