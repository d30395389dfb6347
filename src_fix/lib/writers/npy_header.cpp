// SPDX-License-Identifier: GPL-2.0-or-later
#include "writers/npy_header.h"

#include <stdexcept>

namespace ohmdem {

namespace {
constexpr std::size_t kRowsWidth = 20;  // digits of the largest uint64, 18446744073709551615
constexpr std::size_t kAlign = 64;      // numpy pads its headers to 64 bytes (format 1.0, 2.0)

void check_name(const std::string &c)
{
  if (c.empty()) throw std::invalid_argument("an empty column name cannot go into an .npy header");
  for (const unsigned char ch : c)
    if (ch == '\'' || ch == '\\' || ch < 0x20 || ch == 0x7f)
      throw std::invalid_argument("column name '" + c +
                                  "' cannot go into an .npy header (no quotes, backslashes "
                                  "or control characters)");
}

bool little_endian()
{
  const std::uint16_t probe = 1;
  return *reinterpret_cast<const unsigned char *>(&probe) == 1;
}
}  // namespace

std::string npy_rows_field(std::uint64_t rows)
{
  std::string digits = std::to_string(rows);
  return std::string(kRowsWidth - digits.size(), ' ') + digits;
}

NpyHeader npy_table_header(const std::vector<std::string> &columns, std::uint64_t rows)
{
  if (columns.empty()) throw std::invalid_argument("an .npy table needs at least one column");
  const char *f8 = little_endian() ? "'<f8'" : "'>f8'";
  std::string dict = "{'descr': [";
  for (std::size_t i = 0; i < columns.size(); ++i) {
    check_name(columns[i]);
    dict += (i ? ", ('" : "('") + columns[i] + "', " + f8 + ")";
  }
  dict += "], 'fortran_order': False, 'shape': (";
  const std::size_t rows_at = dict.size();
  dict += npy_rows_field(rows) + ",), }";
  // magic (6) + version (2) + header length (2 in version 1.0, 4 in 2.0) + dict + padding + \n
  std::size_t prefix = 10;
  if (dict.size() + 1 + kAlign > 65535) prefix = 12;
  const std::size_t total = (prefix + dict.size() + 1 + kAlign - 1) / kAlign * kAlign;
  const std::size_t len = total - prefix;
  NpyHeader h;
  h.bytes = "\x93NUMPY";
  h.bytes += prefix == 10 ? '\x01' : '\x02';
  h.bytes += '\x00';
  const int len_bytes = prefix == 10 ? 2 : 4;
  for (int k = 0; k < len_bytes; ++k) h.bytes += static_cast<char>((len >> (8 * k)) & 0xff);
  h.bytes += dict;
  h.bytes.append(total - h.bytes.size() - 1, ' ');
  h.bytes += '\n';
  h.rows_offset = prefix + rows_at;
  h.rows_width = kRowsWidth;
  return h;
}

}  // namespace ohmdem
