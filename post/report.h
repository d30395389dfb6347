// Tabular command output in three forms: an aligned text table (default), CSV (header row with
// units in the column names, '#' metadata lines) and JSON.
#ifndef OHMDEM_POST_REPORT_H
#define OHMDEM_POST_REPORT_H

#include <ostream>
#include <string>
#include <vector>

#include "json.h"
#include "sampled_signal.h"

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

struct Report {
  MetaList meta;
  std::vector<std::string> columns;  // with units: "frequency_Hz", "amplitude_ohm"
  std::vector<std::vector<Cell>> rows;
  int table_digits = 6;  // significant digits in the aligned table (CSV: 12)
};

void write_table(std::ostream &out, const Report &r);
void write_csv(std::ostream &out, const Report &r);
// {"meta": {...}, "columns": [...], "rows": [{column: value, ...}, ...]}
Json report_json(const Report &r);
void write_report(std::ostream &out, const Report &r, OutputFormat f);

Json meta_json(const MetaList &meta);
std::string format_cell(const Cell &c, int digits);  // numbers %.{digits}g, non-finite "n/a"

}  // namespace ohmdem::post

#endif
