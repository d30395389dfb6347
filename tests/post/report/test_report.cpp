// SPDX-License-Identifier: GPL-2.0-or-later
// The shared renderers of command results: the same Result as an aligned table (its own
// layout or its table), CSV (metadata, header, 12 digits, empty undefined cells) and JSON (its
// own document or {"meta", "columns", "rows"}).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "report/report.h"

namespace ohmdem::post {
namespace {

Result sample()
{
  Result r;
  r.meta = {{"source", "x.txt"}, {"window", "hann"}};
  r.table.columns = {"label", "frequency_Hz", "amplitude_ohm"};
  r.table.rows = {{"1xBPFO", 36.0, 0.25}, {"2xBPFO", 72.0, NAN}};
  return r;
}

std::string render(const Result &r, OutputFormat f)
{
  std::ostringstream out;
  write_result(out, r, f);
  return out.str();
}

TEST(Report, TableFormAlignsTheTable)
{
  EXPECT_EQ(render(sample(), OutputFormat::Table),
            "# source: x.txt\n"
            "# window: hann\n"
            "label   frequency_Hz  amplitude_ohm\n"
            "1xBPFO            36           0.25\n"
            "2xBPFO            72            n/a\n");
}

TEST(Report, CsvFormHasHeaderAndEmptyUndefinedCells)
{
  EXPECT_EQ(render(sample(), OutputFormat::Csv),
            "# source: x.txt\n"
            "# window: hann\n"
            "label,frequency_Hz,amplitude_ohm\n"
            "1xBPFO,36,0.25\n"
            "2xBPFO,72,\n");
}

TEST(Report, JsonFormDefaultsToTheTable)
{
  EXPECT_EQ(render(sample(), OutputFormat::Json),
            "{\n"
            "  \"meta\": {\n"
            "    \"source\": \"x.txt\",\n"
            "    \"window\": \"hann\"\n"
            "  },\n"
            "  \"columns\": [\"label\", \"frequency_Hz\", \"amplitude_ohm\"],\n"
            "  \"rows\": [\n"
            "    {\n"
            "      \"label\": \"1xBPFO\",\n"
            "      \"frequency_Hz\": 36,\n"
            "      \"amplitude_ohm\": 0.25\n"
            "    },\n"
            "    {\n"
            "      \"label\": \"2xBPFO\",\n"
            "      \"frequency_Hz\": 72,\n"
            "      \"amplitude_ohm\": null\n"
            "    }\n"
            "  ]\n"
            "}\n");
}

TEST(Report, OwnLayoutAndDocumentReplaceTheTableInTheirForms)
{
  Result r = sample();
  Table t;
  t.columns = {"family", "score"};
  t.rows = {{"outer", 0.9}};
  r.text = {{"defect:  outer", std::nullopt}, {"", std::nullopt}, {"", t}};
  r.json = Json::object();
  r.json.set("defect", "outer");
  EXPECT_EQ(render(r, OutputFormat::Table),
            "# source: x.txt\n"
            "# window: hann\n"
            "defect:  outer\n"
            "\n"
            "family  score\n"
            "outer     0.9\n");
  EXPECT_EQ(render(r, OutputFormat::Json), "{\n  \"defect\": \"outer\"\n}\n");
  // CSV stays the table's
  EXPECT_EQ(render(r, OutputFormat::Csv), render(sample(), OutputFormat::Csv));
}

}  // namespace
}  // namespace ohmdem::post
