// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/read_log.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/text_scan.h"
#include "io/line_reader.h"

namespace ohmdem::post {

bool looks_like_log(const std::string &first_line)
{
  std::string_view s = trim(first_line);
  return starts_with(s, "LIGGGHTS (") || starts_with(s, "LAMMPS (");
}

double log_timestep(const std::string &path)
{
  LineReader in(path);
  std::string line;
  std::vector<std::string_view> tok;
  double dt = 0;
  while (in.next(line)) {
    split_blanks(line, tok);
    double v = 0;
    if (tok.size() == 2 && tok[0] == "timestep" && parse_double(tok[1], v) && std::isfinite(v) &&
        v > 0)
      dt = v;
  }
  if (!(dt > 0)) throw Error(in.name() + ": no 'timestep' command in this log");
  return dt;
}

std::vector<LogBlock> read_log(const std::string &path)
{
  LineReader in(path);
  return read_log(in);
}

std::vector<LogBlock> read_log(LineReader &in)
{
  std::vector<LogBlock> blocks;
  std::string line;
  std::vector<std::string_view> tok;
  double timestep = 0;
  bool inside = false;
  while (in.next(line)) {
    std::string_view s = trim(line);
    if (!inside) {
      split_blanks(s, tok);
      if (tok.size() == 2 && tok[0] == "timestep") {
        double v = 0;
        if (parse_double(tok[1], v) && std::isfinite(v) && v > 0) timestep = v;
      } else if (!tok.empty() && tok[0] == "Step") {
        LogBlock b;
        b.table.source = in.name();
        for (auto w : tok) b.table.names.emplace_back(w);
        b.table.has_header = true;
        b.table.init_columns(tok.size());
        b.timestep = timestep;
        blocks.push_back(std::move(b));
        inside = true;
      }
      continue;
    }
    if (starts_with(s, "Loop time of")) {
      inside = false;
      continue;
    }
    LogBlock &b = blocks.back();
    split_blanks(s, tok);
    const std::size_t ncol = b.table.names.size();
    bool ok = tok.size() == ncol;
    double v = 0;
    for (std::size_t c = 0; ok && c < ncol; ++c) ok = parse_double(tok[c], v);
    if (!ok) {  // LIGGGHTS prints INFO:/WARNING: and insertion messages between thermo rows
      if (!s.empty()) ++b.skipped;
      continue;
    }
    for (std::size_t c = 0; c < ncol; ++c) {
      parse_double(tok[c], v);
      b.table.columns[c].push_back(v);
      b.table.note_token(c, tok[c], v);
    }
    b.table.line_of_row.push_back(in.line_number());
  }
  blocks.erase(std::remove_if(blocks.begin(), blocks.end(),
                              [](const LogBlock &b) { return b.table.rows() == 0; }),
               blocks.end());
  if (blocks.empty())
    throw Error(in.name() +
                ": no thermo block found (a header line starting with 'Step' followed by "
                "rows of numbers)");
  return blocks;
}

}  // namespace ohmdem::post
