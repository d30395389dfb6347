// SPDX-License-Identifier: GPL-2.0-or-later
#include "report/report.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace ohmdem::post {

OutputFormat parse_output_format(const std::string &name)
{
  if (name == "table") return OutputFormat::Table;
  if (name == "csv") return OutputFormat::Csv;
  if (name == "json") return OutputFormat::Json;
  throw SettingError("option {report.format} expects table|csv|json, got '" + name + "'");
}

std::string format_cell(const Cell &c, int digits)
{
  if (!c.is_number) return c.text;
  if (!std::isfinite(c.number)) return "n/a";
  return format_number(c.number, digits);
}

void write_meta(std::ostream &out, const MetaList &meta)
{
  for (const auto &m : meta) out << "# " << m.first << ": " << m.second << '\n';
}

void write_table(std::ostream &out, const Table &r)
{
  const std::size_t nc = r.columns.size();
  if (nc == 0) return;
  std::vector<std::size_t> width(nc);
  std::vector<std::vector<std::string>> text(r.rows.size(), std::vector<std::string>(nc));
  for (std::size_t c = 0; c < nc; ++c) width[c] = r.columns[c].size();
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    for (std::size_t c = 0; c < nc && c < r.rows[i].size(); ++c) {
      text[i][c] = format_cell(r.rows[i][c], r.table_digits);
      width[c] = std::max(width[c], text[i][c].size());
    }
  auto pad = [&](const std::string &s, std::size_t w, bool right) {
    std::string f(w > s.size() ? w - s.size() : 0, ' ');
    return right ? f + s : s + f;
  };
  std::string head;
  for (std::size_t c = 0; c < nc; ++c) {
    const bool right = r.rows.empty() || c >= r.rows[0].size() || r.rows[0][c].is_number;
    head += (c ? "  " : "") + pad(r.columns[c], width[c], right);
  }
  while (!head.empty() && head.back() == ' ') head.pop_back();
  out << head << '\n';
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    std::string line;
    for (std::size_t c = 0; c < nc; ++c) {
      const bool right = c < r.rows[i].size() ? r.rows[i][c].is_number : true;
      line += (c ? "  " : "") + pad(text[i][c], width[c], right);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  }
}

namespace {
std::string csv_text(const std::string &s)
{
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}
}  // namespace

void write_csv(std::ostream &out, const Table &r)
{
  for (std::size_t c = 0; c < r.columns.size(); ++c)
    out << (c ? "," : "") << csv_text(r.columns[c]);
  out << '\n';
  for (const auto &row : r.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      out << (c ? "," : "");
      if (row[c].is_number)
        out << (std::isfinite(row[c].number) ? format_number(row[c].number, 12) : "");
      else
        out << csv_text(row[c].text);
    }
    out << '\n';
  }
}

Json meta_json(const MetaList &meta)
{
  Json m = Json::object();
  for (const auto &kv : meta) m.set(kv.first, kv.second);
  return m;
}

Json table_json(const Table &r, const MetaList &meta)
{
  Json j = Json::object();
  j.set("meta", meta_json(meta));
  Json cols = Json::array();
  for (const auto &c : r.columns) cols.push_back(c);
  j.set("columns", cols);
  Json rows = Json::array();
  for (const auto &row : r.rows) {
    Json o = Json::object();
    for (std::size_t c = 0; c < row.size() && c < r.columns.size(); ++c)
      o.set(r.columns[c], row[c].is_number ? Json(row[c].number) : Json(row[c].text));
    rows.push_back(o);
  }
  j.set("rows", rows);
  return j;
}

void write_result(std::ostream &out, const Result &r, OutputFormat f)
{
  switch (f) {
    case OutputFormat::Table:
      write_meta(out, r.meta);
      if (r.text.empty()) write_table(out, r.table);
      for (const Block &b : r.text) {
        if (b.table)
          write_table(out, *b.table);
        else
          out << b.line << '\n';
      }
      break;
    case OutputFormat::Csv:
      write_meta(out, r.meta);
      write_csv(out, r.table);
      break;
    case OutputFormat::Json:
      out << (r.json.is_null() ? table_json(r.table, r.meta) : r.json).dump(2) << '\n';
      break;
  }
}

std::string with_unit(const std::string &name, const std::string &unit)
{
  return unit.empty() ? name : name + "_" + unit;
}

}  // namespace ohmdem::post
