// SPDX-License-Identifier: GPL-2.0-or-later
// What a command found, built once as a Result, and the shared renderers that print it in the
// three output forms: an aligned text table (default), CSV (header row with units in the column
// names, '#' metadata lines) and JSON.
#ifndef OHMDEM_POST_REPORT_H
#define OHMDEM_POST_REPORT_H

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/sampled_signal.h"
#include "io/json.h"

namespace ohmdem::post {

enum class OutputFormat { Table, Csv, Json };
OutputFormat parse_output_format(const std::string &name);

struct Cell {
  Cell(double v) : is_number(true), number(v) {}
  Cell(int v) : is_number(true), number(v) {}
  Cell(std::size_t v) : is_number(true), number(static_cast<double>(v)) {}
  Cell(std::string s) : text(std::move(s)) {}
  Cell(const char *s) : text(s) {}
  bool is_number = false;
  double number = 0;
  std::string text;
};

// Named columns (units in the names: "frequency_Hz", "amplitude_ohm") and rows of cells.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
  int table_digits = 6;  // significant digits in the aligned table (CSV: 12)
};

// One piece of a result's aligned-table form: a text line, or a table when `table` is set.
struct Block {
  std::string line;
  std::optional<Table> table;
};

struct Result {
  MetaList meta;            // '#' lines of the table and CSV forms, "meta" of the JSON form
  Table table;              // CSV; also the aligned table and JSON unless given below
  std::vector<Block> text;  // the aligned-table form when richer than `table` (verdict, tables)
  Json json;                // the JSON form when not {"meta", "columns", "rows"} of `table`
};

// `f` picks the form: the aligned `text` (else `table`), the CSV of `table`, `json` (else
// `table`'s); the metadata heads the table and CSV forms as '# key: value' lines.
void write_result(std::ostream &out, const Result &r, OutputFormat f);

void write_meta(std::ostream &out, const MetaList &meta);  // "# key: value" lines
void write_table(std::ostream &out, const Table &t);       // aligned columns
void write_csv(std::ostream &out, const Table &t);         // header row, then rows
// {"meta": {...}, "columns": [...], "rows": [{column: value, ...}, ...]}
Json table_json(const Table &t, const MetaList &meta);

Json meta_json(const MetaList &meta);
std::string format_cell(const Cell &c, int digits);  // numbers %.{digits}g, non-finite "n/a"

// A column name with its unit: "amplitude_ohm" ("amplitude" when the unit is unknown).
std::string with_unit(const std::string &name, const std::string &unit);

}  // namespace ohmdem::post

#endif
