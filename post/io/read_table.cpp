// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/read_table.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/text_scan.h"
#include "io/line_reader.h"
#include "io/read_npy.h"

namespace ohmdem::post {

namespace {

std::string quoted(std::string_view s)
{
  std::string q(s.substr(0, 40));
  for (char &c : q)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  if (s.size() > 40) q += "...";
  return "'" + q + "'";
}

}  // namespace

namespace {

// The cells of a CSV line; a comma between double quotes ("a, b", as write_csv quotes text
// holding commas) does not split.
std::vector<std::string_view> split_commas(std::string_view line)
{
  std::vector<std::string_view> out;
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0;; ++i) {
    if (i == line.size() || (line[i] == ',' && !quoted)) {
      out.push_back(trim(line.substr(start, i - start)));
      if (i == line.size()) break;
      start = i + 1;
    } else if (line[i] == '"') {
      quoted = !quoted;
    }
  }
  return out;
}

// A quoted cell without its quotes, a doubled quote inside read as one.
std::string unquote(std::string_view s)
{
  if (s.size() < 2 || s.front() != '"' || s.back() != '"') return std::string(s);
  std::string out;
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    out += s[i];
    if (s[i] == '"' && i + 2 < s.size() && s[i + 1] == '"') ++i;
  }
  return out;
}

// Which columns to store, asked once the names are known.
void choose_columns(ColumnTable &t, const TableOptions &opt)
{
  if (!opt.keep) return;
  std::vector<bool> keep = opt.keep(t);
  keep.resize(t.cols(), false);
  t.stored = keep;
}

// Reserves the kept columns for the rows a regular file will hold, estimated from the bytes
// per row so far: the columns then grow without copies (untouched capacity costs no memory).
void reserve_rows(ColumnTable &t, const LineReader &in)
{
  if (in.size_hint() == 0 || in.bytes_consumed() == 0) return;
  const double per_row = static_cast<double>(in.bytes_consumed()) /
                         static_cast<double>(std::max<std::size_t>(t.rows(), 1));
  const auto expect =
      static_cast<std::size_t>(static_cast<double>(in.size_hint()) / per_row * 1.25) + 64;
  for (std::size_t c = 0; c < t.cols(); ++c)
    if (t.stored[c]) t.columns[c].reserve(expect);
}

constexpr std::size_t kRowsBeforeReserve = 256;

ColumnTable read_csv(LineReader &in, ColumnTable t, std::string first, const TableOptions &opt)
{
  std::string line = std::move(first);
  std::size_t ncol = 0;
  do {
    std::string_view s = trim(line);
    if (s.empty() || s.front() == '#') continue;
    const auto cells = split_commas(s);
    if (ncol == 0) {
      ncol = cells.size();
      t.init_columns(ncol);
      double v = 0;
      bool header = false;
      for (auto c : cells) header = header || !parse_double(c, v);
      if (header) {
        for (auto c : cells) t.names.push_back(unquote(c));
        t.has_header = true;
      } else {
        for (std::size_t c = 0; c < ncol; ++c) t.names.push_back(std::to_string(c + 1));
      }
      choose_columns(t, opt);
      if (opt.header_only) return t;
      if (header) continue;
    }
    if (cells.size() != ncol)
      throw Error(in.where() + ": " + std::to_string(cells.size()) + " cells, expected " +
                  std::to_string(ncol) + " as on the header (garbage or truncated line?)");
    for (std::size_t c = 0; c < ncol; ++c) {
      double v = 0;
      if (!parse_double(cells[c], v)) {
        v = std::nan("");
        if (t.first_text[c].empty()) {
          t.first_text[c] = cells[c].empty() ? "(empty)" : unquote(cells[c]);
          t.first_text_line[c] = in.line_number();
        }
        if (t.stored[c]) {
          t.text[c].resize(t.rows());  // the rows before: numbers
          t.text[c].push_back(unquote(cells[c]));
        }
      } else if (!t.text[c].empty()) {
        t.text[c].emplace_back();
      }
      if (!t.stored[c]) continue;
      t.columns[c].push_back(v);
      t.note_token(c, cells[c], v);
    }
    t.line_of_row.push_back(in.line_number());
    if (t.rows() == kRowsBeforeReserve) reserve_rows(t, in);
  } while (in.next(line));
  if (t.rows() == 0) throw Error(t.source + ": no data rows (empty file or only a header)");
  return t;
}

}  // namespace

ColumnTable read_table(const std::string &path, const TableOptions &opt)
{
  if (has_npy_header(path)) return read_npy(path, opt);  // binary: fix signal/table format npy
  LineReader in(path, opt.max_line);
  return read_table(in, opt);
}

ColumnTable read_table(LineReader &in, const TableOptions &opt)
{
  ColumnTable t;
  t.source = in.name();
  std::string line;
  std::string last_comment;
  bool comment_just_before = false;
  std::vector<std::string_view> tok;
  std::vector<double> values;
  std::size_t ncol = 0;
  while (in.next(line)) {
    std::string_view s = trim(line);
    if (s.empty()) continue;
    if (s.front() == '#') {
      if (ncol == 0) {
        last_comment = std::string(s.substr(1));
        comment_just_before = true;
        t.notes.emplace_back(s);
        if (last_comment.find("Number-of-rows") != std::string::npos)
          throw Error(in.where() +
                      ": fix ave/time files in 'mode vector' are not supported; write the "
                      "quantity with 'mode scalar' or a dump");
      }
      continue;
    }
    if (ncol == 0 && s.find(',') != std::string_view::npos)
      return read_csv(in, std::move(t), line, opt);
    split_blanks(s, tok);
    if (ncol == 0) {
      ncol = tok.size();
      auto words = split_blanks(last_comment);
      if (comment_just_before && words.size() == ncol) {
        for (auto w : words) t.names.emplace_back(w);
        t.has_header = true;
      } else {
        for (std::size_t c = 0; c < ncol; ++c) t.names.push_back(std::to_string(c + 1));
        if (comment_just_before && !words.empty())
          t.notes.push_back("header line has " + std::to_string(words.size()) +
                            " words but rows have " + std::to_string(ncol) +
                            " values: columns are numbered");
      }
      t.init_columns(ncol);
      choose_columns(t, opt);
      if (opt.header_only) return t;
      values.assign(ncol, 0.0);
    }
    std::string bad;
    if (tok.size() != ncol)
      bad = in.where() + ": " + std::to_string(tok.size()) + " values, expected " +
            std::to_string(ncol) + " as on the first data row (garbage or truncated line?)";
    for (std::size_t c = 0; bad.empty() && c < ncol; ++c)
      if (!parse_double(tok[c], values[c]))
        bad = in.where() + ": " + quoted(tok[c]) + " is not a number (column " + t.names[c] + ")";
    if (!bad.empty()) {
      // A last line without its line break was cut (a crash, a full disk): the rows before
      // it are good. Anywhere else a bad row is an error.
      if (!in.line_unterminated() || t.rows() == 0) throw Error(bad);
      warn(in.where() +
           ": dropped the last row, cut before its end (a run stopped while "
           "writing it: a crash or a full disk): " +
           bad.substr(bad.find(": ") + 2));
      break;
    }
    for (std::size_t c = 0; c < ncol; ++c) {
      if (!t.stored[c]) continue;
      t.columns[c].push_back(values[c]);
      t.note_token(c, tok[c], values[c]);
    }
    t.line_of_row.push_back(in.line_number());
    if (t.rows() == kRowsBeforeReserve) reserve_rows(t, in);
  }
  if (t.rows() == 0 && !(opt.header_only && ncol > 0))
    throw Error(t.source + ": no data rows (empty file or only comments)");
  return t;
}

}  // namespace ohmdem::post
