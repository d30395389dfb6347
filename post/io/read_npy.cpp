// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/read_npy.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "core/error.h"

namespace ohmdem::post {

namespace {

struct Field {
  std::string name;
  char kind = 'f';  // f float, i signed, u unsigned
  int bytes = 8;
};

struct Layout {
  std::vector<Field> fields;  // records: one per field; plain arrays: one, repeated
  bool records = false;
  bool fortran = false;
  std::vector<std::uint64_t> shape;
  std::uint64_t data_offset = 0;
};

// A small parser for the header's Python dict literal: strings, True/False, tuples of
// integers, and the list of (name, type) tuples of a record type.
class HeaderParser {
 public:
  HeaderParser(std::string text, std::string path) : s_(std::move(text)), path_(std::move(path)) {}

  Layout parse()
  {
    Layout l;
    bool descr = false, order = false, shape = false;
    expect('{');
    while (!peek('}')) {
      const std::string key = string();
      expect(':');
      if (key == "descr") {
        descr = true;
        if (peek('[')) {
          l.records = true;
          expect('[');
          while (!peek(']')) {
            expect('(');
            Field f;
            f.name = string();
            expect(',');
            type(string(), f);
            if (!peek(')')) fail("field '" + f.name + "' has a sub-array shape (not supported)");
            expect(')');
            l.fields.push_back(f);
            if (!peek(']')) expect(',');
          }
          expect(']');
          if (l.fields.empty()) fail("a record type without fields");
        } else {
          Field f;
          type(string(), f);
          l.fields.push_back(f);
        }
      } else if (key == "fortran_order") {
        order = true;
        l.fortran = word() == "True";
      } else if (key == "shape") {
        shape = true;
        expect('(');
        while (!peek(')')) {
          l.shape.push_back(integer());
          if (!peek(')')) expect(',');
        }
        expect(')');
      } else {
        fail("unknown key '" + key + "'");
      }
      if (!peek('}')) expect(',');
    }
    if (!descr || !order || !shape) fail("the header lacks descr, fortran_order or shape");
    return l;
  }

 private:
  [[noreturn]] void fail(const std::string &what) const
  {
    throw Error(path_ + ": not a readable .npy header: " + what);
  }
  void blanks()
  {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t')) ++i_;
  }
  bool peek(char c)
  {
    blanks();
    return i_ < s_.size() && s_[i_] == c;
  }
  void expect(char c)
  {
    if (!peek(c)) fail(std::string("expected '") + c + "' at byte " + std::to_string(i_));
    ++i_;
  }
  std::string string()
  {
    blanks();
    if (i_ >= s_.size() || (s_[i_] != '\'' && s_[i_] != '"')) fail("expected a quoted string");
    const char q = s_[i_++];
    const std::size_t end = s_.find(q, i_);
    if (end == std::string::npos) fail("an unterminated string");
    std::string out = s_.substr(i_, end - i_);
    i_ = end + 1;
    return out;
  }
  std::string word()
  {
    blanks();
    const std::size_t start = i_;
    while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
    std::string w = s_.substr(start, i_ - start);
    if (w != "True" && w != "False") fail("fortran_order must be True or False");
    return w;
  }
  std::uint64_t integer()
  {
    blanks();
    const std::size_t start = i_;
    while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    if (i_ == start) fail("a shape entry is not a whole number");
    // More digits than 2^64 holds is no file's shape (stoull would throw out_of_range).
    const std::string digits = s_.substr(start, i_ - start);
    errno = 0;
    const unsigned long long v = std::strtoull(digits.c_str(), nullptr, 10);
    if (errno == ERANGE) fail("a shape entry (" + digits.substr(0, 24) + ") is beyond 2^64");
    return v;
  }
  void type(const std::string &t, Field &f) const
  {
    // '<f8', '|u1', '=i4': byte order, kind, size. Big-endian data would need swapping.
    const std::uint16_t probe = 1;
    const bool little = *reinterpret_cast<const unsigned char *>(&probe) == 1;
    if (t.size() < 3 || std::string("<>|=").find(t[0]) == std::string::npos)
      fail("element type '" + t + "' is not supported");
    const bool big = t[0] == '>' || (t[0] == '=' && !little);
    f.kind = t[1];
    f.bytes = std::atoi(t.c_str() + 2);
    const bool ok = (f.kind == 'f' && (f.bytes == 4 || f.bytes == 8)) ||
                    ((f.kind == 'i' || f.kind == 'u') &&
                     (f.bytes == 1 || f.bytes == 2 || f.bytes == 4 || f.bytes == 8));
    if (!ok)
      fail("element type '" + t +
           "' is not supported (float64, float32 and integers are: convert with astype)");
    if (big && f.bytes > 1 && little)
      fail("big-endian element type '" + t + "': convert with a.astype('<" + t.substr(1) + "')");
  }

  std::string s_, path_;
  std::size_t i_ = 0;
};

double value(const unsigned char *p, const Field &f)
{
  switch (f.kind) {
    case 'f':
      if (f.bytes == 8) {
        double d;
        std::memcpy(&d, p, 8);
        return d;
      } else {
        float x;
        std::memcpy(&x, p, 4);
        return x;
      }
    case 'i':
      switch (f.bytes) {
        case 1:
          return static_cast<std::int8_t>(*p);
        case 2: {
          std::int16_t v;
          std::memcpy(&v, p, 2);
          return v;
        }
        case 4: {
          std::int32_t v;
          std::memcpy(&v, p, 4);
          return v;
        }
        default: {
          std::int64_t v;
          std::memcpy(&v, p, 8);
          return static_cast<double>(v);
        }
      }
    default:
      switch (f.bytes) {
        case 1:
          return *p;
        case 2: {
          std::uint16_t v;
          std::memcpy(&v, p, 2);
          return v;
        }
        case 4: {
          std::uint32_t v;
          std::memcpy(&v, p, 4);
          return v;
        }
        default: {
          std::uint64_t v;
          std::memcpy(&v, p, 8);
          return static_cast<double>(v);
        }
      }
  }
}

Layout read_layout(std::ifstream &in, const std::string &path)
{
  unsigned char head[12] = {};
  if (!in.read(reinterpret_cast<char *>(head), 10) || std::memcmp(head, "\x93NUMPY", 6) != 0)
    throw Error(path + ": not an .npy file (no \\x93NUMPY magic)");
  const int major = head[6];
  std::uint64_t len = head[8] | (head[9] << 8);
  std::uint64_t prefix = 10;
  if (major == 2 || major == 3) {
    if (!in.read(reinterpret_cast<char *>(head + 10), 2))
      throw Error(path + ": truncated .npy header");
    len = head[8] | (head[9] << 8) | (std::uint64_t(head[10]) << 16) |
          (std::uint64_t(head[11]) << 24);
    prefix = 12;
  } else if (major != 1) {
    throw Error(path + ": .npy format version " + std::to_string(major) +
                " is not supported (1-3 are)");
  }
  // The header's length against the file before allocating it (a lying length is no reason
  // to allocate gigabytes).
  const std::uint64_t size = std::filesystem::file_size(path);
  if (len > size - std::min(size, prefix))
    throw Error(path + ": truncated .npy header: its length field says " + std::to_string(len) +
                " bytes, the file holds " + std::to_string(size) + " in all");
  std::string text(len, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(len)))
    throw Error(path + ": truncated .npy header");
  Layout l = HeaderParser(text, path).parse();
  l.data_offset = prefix + len;
  return l;
}

std::string type_name(const Field &f)
{
  return "<" + std::string(1, f.kind) + std::to_string(f.bytes);
}

}  // namespace

bool has_npy_header(const std::string &path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path, std::ios::binary);
  char magic[6] = {};
  return in.read(magic, 6) && std::memcmp(magic, "\x93NUMPY", 6) == 0;
}

ColumnTable read_npy(const std::string &path, const TableOptions &opt)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be opened");
  const Layout l = read_layout(in, path);
  ColumnTable t;
  t.source = path;
  // Columns: the fields of a record array; else 1 (1-D) or shape[1] (2-D) unnamed ones.
  std::uint64_t rows = 0, cols = 0;
  if (l.records) {
    if (l.shape.size() != 1)
      throw Error(path + ": a record array of " + std::to_string(l.shape.size()) +
                  " dimensions (1 is readable: one record per row)");
    rows = l.shape[0];
    cols = l.fields.size();
    for (const auto &f : l.fields) t.names.push_back(f.name);
    t.has_header = true;
  } else {
    if (l.shape.empty() || l.shape.size() > 2)
      throw Error(path + ": an array of " + std::to_string(l.shape.size()) +
                  " dimensions (1: one column, 2: rows x columns)");
    rows = l.shape[0];
    cols = l.shape.size() == 2 ? l.shape[1] : 1;
    if (cols == 0) throw Error(path + ": an array without columns");
    // A row must fit in the file before the columns are made (a shape of 1e18 columns).
    const std::uint64_t size = std::filesystem::file_size(path);
    const std::uint64_t data = size - std::min(size, l.data_offset);
    const std::uint64_t limit = rows > 0 ? data / l.fields[0].bytes : std::uint64_t(1) << 20;
    if (cols > limit)
      throw Error(path + ": the header's shape gives " + std::to_string(cols) +
                  " columns, more than the file's " + std::to_string(data) + " data bytes hold");
    for (std::uint64_t c = 1; c <= cols; ++c) t.names.push_back(std::to_string(c));
  }
  t.init_columns(cols);
  if (opt.keep) {
    std::vector<bool> keep = opt.keep(t);
    keep.resize(cols, false);
    t.stored = keep;
  }
  if (opt.header_only) return t;
  std::uint64_t row_bytes = 0;
  for (std::uint64_t c = 0; c < cols; ++c) row_bytes += l.fields[l.records ? c : 0].bytes;
  const std::uint64_t size = std::filesystem::file_size(path);
  const std::uint64_t present = (size - std::min(size, l.data_offset)) / row_bytes;
  const std::uint64_t cut = (size - std::min(size, l.data_offset)) % row_bytes;
  // Rows the header counts are never dropped: a file cut inside them is refused (as numpy.load
  // refuses it). A row cut after them (fix signal/table stopped while writing rows it had not
  // counted yet) is dropped with a warning, the whole ones kept.
  if (present < rows)
    throw Error(path + ": truncated: the header counts " + std::to_string(rows) +
                " rows, the file holds " + std::to_string(present) +
                (cut ? " whole rows and " + std::to_string(cut) + " of the next row's " +
                           std::to_string(row_bytes) + " bytes"
                     : std::string()) +
                " (a cut file; numpy.load refuses it too)");
  if (l.records && cut)
    warn(path +
         ": dropped the last row, cut before its end (a run stopped while writing it: a "
         "crash or a full disk): " +
         std::to_string(cut) + " of its " + std::to_string(row_bytes) + " bytes");
  // More data than the header describes: a record table may hold uncounted rows (fix
  // signal/table stopped between writing a block and counting it: one block at most, fewer
  // than the rows counted before); anything else means an element type that is not the data's
  // (a '<i4' or '<f4' header on float64 data: twice the bytes, read as garbage).
  const std::uint64_t data_bytes = size - std::min(size, l.data_offset);
  const bool uncounted = l.records && (rows == 0 || present < 2 * rows);
  if (data_bytes / row_bytes != rows && !uncounted) {
    std::string types;
    for (const auto &f : l.fields)
      if (types.find(type_name(f)) == std::string::npos)
        types += (types.empty() ? "'" : ", '") + type_name(f) + "'";
    throw Error(path + ": the header's element type " + types + " and shape give " +
                std::to_string(rows * row_bytes) + " data bytes, the file holds " +
                std::to_string(data_bytes) +
                ": the header does not describe the data (another element type? float64 is "
                "'<f8'); write it again with numpy.save");
  }
  if (l.records && present > rows) {
    t.notes.push_back("read " + std::to_string(present - rows) +
                      " whole rows beyond the header's count (a run stopped before counting "
                      "them; numpy.load reads the counted rows only)");
    rows = present;
  }
  for (std::uint64_t c = 0; c < cols; ++c)
    if (t.stored[c]) t.columns[c].resize(rows);
  // Read in blocks of rows; a Fortran-ordered 2-D array is stored column after column.
  std::vector<unsigned char> block;
  const std::uint64_t per_block = std::max<std::uint64_t>(1, (1u << 20) / row_bytes);
  if (l.fortran && !l.records && cols > 1) {
    const Field &f = l.fields[0];
    block.resize(rows * f.bytes);
    for (std::uint64_t c = 0; c < cols; ++c) {
      in.seekg(static_cast<std::streamoff>(l.data_offset + c * rows * f.bytes));
      if (!in.read(reinterpret_cast<char *>(block.data()),
                   static_cast<std::streamsize>(block.size())))
        throw Error(path + ": could not be read");
      if (t.stored[c])
        for (std::uint64_t r = 0; r < rows; ++r) t.columns[c][r] = value(&block[r * f.bytes], f);
    }
  } else {
    in.seekg(static_cast<std::streamoff>(l.data_offset));
    for (std::uint64_t r0 = 0; r0 < rows; r0 += per_block) {
      const std::uint64_t n = std::min(per_block, rows - r0);
      block.resize(n * row_bytes);
      if (!in.read(reinterpret_cast<char *>(block.data()),
                   static_cast<std::streamsize>(block.size())))
        throw Error(path + ": could not be read past row " + std::to_string(r0));
      for (std::uint64_t r = 0; r < n; ++r) {
        const unsigned char *p = &block[r * row_bytes];
        for (std::uint64_t c = 0; c < cols; ++c) {
          const Field &f = l.fields[l.records ? c : 0];
          if (t.stored[c]) t.columns[c][r0 + r] = value(p, f);
          p += f.bytes;
        }
      }
    }
  }
  // Binary values are exact: full precision, and each row's number as its "line".
  for (std::uint64_t c = 0; c < cols; ++c) {
    t.digits[c] = 17;
    if (!t.stored[c]) continue;
    for (double v : t.columns[c])
      if (std::isfinite(v)) t.max_abs[c] = std::max(t.max_abs[c], std::fabs(v));
  }
  for (std::uint64_t r = 0; r < rows; ++r) t.line_of_row.push_back(r + 1);
  return t;
}

}  // namespace ohmdem::post
