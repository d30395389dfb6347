// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/mat_integrity.h"

#include <sys/stat.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

#include "core/error.h"

namespace ohmdem::post {

namespace {

// MAT v5 data types (MATLAB's "MAT-File Format", table 1-1)
enum : std::uint32_t {
  kInt8 = 1,
  kUint8 = 2,
  kInt16 = 3,
  kUint16 = 4,
  kInt32 = 5,
  kUint32 = 6,
  kSingle = 7,
  kDouble = 9,
  kInt64 = 12,
  kUint64 = 13,
  kMatrix = 14,
  kCompressed = 15,
  kUtf8 = 16,
  kUtf16 = 17,
  kUtf32 = 18,
};

std::size_t type_bytes(std::uint32_t type)
{
  switch (type) {
    case kInt8:
    case kUint8:
    case kUtf8:
      return 1;
    case kInt16:
    case kUint16:
    case kUtf16:
      return 2;
    case kInt32:
    case kUint32:
    case kSingle:
    case kUtf32:
      return 4;
    case kDouble:
    case kInt64:
    case kUint64:
      return 8;
    default:
      return 0;
  }
}

// The array classes whose data are numbers of one type per element (double .. uint64).
bool numeric_class(std::uint32_t c)
{
  return c >= 6 && c <= 15;
}

class Checker {
 public:
  Checker(std::string path, bool swap) : path_(std::move(path)), swap_(swap) {}

  [[noreturn]] void fail(const std::string &what) const
  {
    throw Error(path_ + ": damaged MAT file: " + what);
  }

  // The elements of [at, end) of `b` (the file after its header, or a decompressed stream;
  // `in` says which, for the messages).
  void elements(const std::vector<unsigned char> &b, std::size_t at, std::size_t end,
                const std::string &in)
  {
    while (at < end) {
      const Tag t = tag(b, at, end, element_name(b, at, end) + in);
      if (t.type == kCompressed) {
        const std::vector<unsigned char> z = inflate_element(b, t, in);
        elements(z, 0, z.size(), " of the compressed element at byte " + std::to_string(at) + in);
        at = t.data + t.nbytes;  // a compressed element is not padded
      } else {
        if (t.type == kMatrix) matrix(b, t.data, t.data + t.nbytes, "", in);
        at = t.next;
      }
    }
  }

 private:
  struct Tag {
    std::uint32_t type = 0;
    std::uint64_t nbytes = 0;
    std::size_t data = 0, next = 0;  // where its data begin; where the next element begins
  };

  std::uint32_t u32(const std::vector<unsigned char> &b, std::size_t at) const
  {
    std::uint32_t v = 0;
    std::memcpy(&v, &b[at], 4);
    if (swap_) v = (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
    return v;
  }

  // "variable 'x' at byte 128" when the array's name can be read before `end` (a variable cut
  // after its name), else "the element at byte 128".
  std::string element_name(const std::vector<unsigned char> &b, std::size_t at,
                           std::size_t end) const
  {
    const std::string where = "at byte " + std::to_string(at);
    std::size_t p = at + 8;  // flags, dimensions, name: three elements with tags of 8 bytes
    if (end - at < 8 || u32(b, at) != kMatrix) return "the element " + where;
    for (int k = 0; k < 3; ++k) {
      if (p > end || end - p < 8) return "the element " + where;
      const std::uint32_t w = u32(b, p);
      const std::size_t n = w >> 16 ? w >> 16 : u32(b, p + 4);
      const std::size_t data = p + (w >> 16 ? 4 : 8);
      if (n > end - data) return "the element " + where;
      if (k == 2 && (w >> 16 ? w & 0xffffu : w) == kInt8)
        return "variable '" +
               std::string(b.begin() + static_cast<std::ptrdiff_t>(data),
                           b.begin() + static_cast<std::ptrdiff_t>(data + n)) +
               "' " + where;
      p = w >> 16 ? p + 8 : data + (n + 7) / 8 * 8;
    }
    return "the element " + where;
  }

  // The tag at `at`; its data must fit in [at, end).
  Tag tag(const std::vector<unsigned char> &b, std::size_t at, std::size_t end,
          const std::string &what) const
  {
    if (end - at < 8)
      fail(what + " is cut: " + std::to_string(end - at) +
           " of its 8-byte tag before the end (a cut file)");
    Tag t;
    const std::uint32_t w = u32(b, at);
    if (w >> 16) {  // small element: type and size in one word, up to 4 bytes of data after it
      t.type = w & 0xffffu;
      t.nbytes = w >> 16;
      if (t.nbytes > 4)
        fail(what + " is a small element of " + std::to_string(t.nbytes) + " bytes");
      t.data = at + 4;
      t.next = at + 8;
      return t;
    }
    t.type = w;
    t.nbytes = u32(b, at + 4);
    t.data = at + 8;
    const std::size_t room = end - t.data;
    if (t.nbytes > room)
      fail(what + " holds " + std::to_string(t.nbytes) + " bytes, only " + std::to_string(room) +
           " follow its tag (a cut or truncated file)");
    const std::uint64_t padded = t.type == kCompressed ? t.nbytes : (t.nbytes + 7) / 8 * 8;
    t.next = t.data + static_cast<std::size_t>(std::min<std::uint64_t>(padded, room));
    return t;
  }

  // An array (miMATRIX) in [at, end): flags, dimensions, name, then its data; the arrays it
  // holds (cells, struct fields) are checked the same way.
  void matrix(const std::vector<unsigned char> &b, std::size_t at, std::size_t end,
              const std::string &parent, const std::string &in)
  {
    if (at == end) return;  // an empty array (a cell's empty element)
    const std::string here = parent.empty() ? "a variable at byte " + std::to_string(at) + in
                                            : "an element of " + parent;
    const Tag flags = tag(b, at, end, here + ": its array flags");
    if (flags.type != kUint32 || flags.nbytes < 8) fail(here + " has no array flags");
    const std::uint32_t word = u32(b, flags.data);
    const std::uint32_t cls = word & 0xffu;
    const bool complex = (word & 0x0800u) != 0;
    const Tag dims = tag(b, flags.next, end, here + ": its dimensions");
    if (dims.type != kInt32 || dims.nbytes % 4 != 0 || dims.nbytes == 0)
      fail(here + " has no dimensions");
    std::uint64_t count = 1;
    std::string shape;
    for (std::size_t k = 0; k < dims.nbytes / 4; ++k) {
      const auto d = static_cast<std::int32_t>(u32(b, dims.data + 4 * k));
      if (d < 0) fail(here + " has a negative dimension");
      shape += (shape.empty() ? "" : "x") + std::to_string(d);
      if (d && count > std::numeric_limits<std::uint64_t>::max() / static_cast<std::uint64_t>(d))
        fail(here + " has dimensions beyond any file (" + shape + ")");
      count *= static_cast<std::uint64_t>(d);
    }
    const Tag name = tag(b, dims.next, end, here + ": its name");
    if (name.type != kInt8) fail(here + " has no name");
    const std::string label =
        parent.empty()
            ? "variable '" +
                  std::string(b.begin() + static_cast<std::ptrdiff_t>(name.data),
                              b.begin() + static_cast<std::ptrdiff_t>(name.data + name.nbytes)) +
                  "'"
            : here;
    std::size_t p = name.next;
    if (numeric_class(cls)) {
      // the real part, then the imaginary one: one value of the stored type per element
      for (int part = 0; part < (complex ? 2 : 1); ++part) {
        const std::string what = label + " (" + shape + (part ? "), its imaginary part" : ")");
        const Tag d = tag(b, p, end, what);
        const std::size_t size = type_bytes(d.type);
        if (!size) fail(what + " holds data of unknown type " + std::to_string(d.type));
        if (d.nbytes != count * size)
          fail(what + " holds " + std::to_string(d.nbytes) + " data bytes, its " +
               std::to_string(count) + " elements need " + std::to_string(count * size));
        p = d.next;
      }
    }
    // whatever follows (a cell's or a struct's arrays, a sparse array's indices) must fit too
    while (p < end) {
      const Tag t = tag(b, p, end, label + ": a part at byte " + std::to_string(p) + in);
      if (t.type == kMatrix) matrix(b, t.data, t.data + t.nbytes, label, in);
      p = t.next;
    }
  }

  std::vector<unsigned char> inflate_element(const std::vector<unsigned char> &b, const Tag &t,
                                             const std::string &in) const
  {
    const std::string what = "the compressed element at byte " + std::to_string(t.data - 8) + in;
    z_stream zs{};
    if (inflateInit(&zs) != Z_OK) fail("zlib cannot start decompressing " + what);
    zs.next_in = const_cast<Bytef *>(b.data() + t.data);
    zs.avail_in = static_cast<uInt>(t.nbytes);
    std::vector<unsigned char> out(std::max<std::size_t>(4 * t.nbytes, 1 << 16));
    std::size_t have = 0;
    int rc = Z_OK;
    while (rc == Z_OK) {
      if (have == out.size()) out.resize(2 * out.size());
      zs.next_out = out.data() + have;
      zs.avail_out = static_cast<uInt>(std::min<std::size_t>(out.size() - have, 1u << 30));
      const uInt before = zs.avail_out;
      rc = inflate(&zs, Z_NO_FLUSH);
      have += before - zs.avail_out;
    }
    const std::string why = zs.msg              ? zs.msg
                            : rc == Z_BUF_ERROR ? "its data end before the compressed stream does"
                            : rc == Z_MEM_ERROR ? "out of memory"
                                                : "zlib status " + std::to_string(rc);
    inflateEnd(&zs);
    if (rc != Z_STREAM_END) fail(what + " does not decompress (zlib: " + why + ")");
    out.resize(have);
    return out;
  }

  std::string path_;
  bool swap_;
};

std::vector<unsigned char> slurp(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
  // a block at a time: byte by byte through an istreambuf_iterator cost as much as the reading
  std::vector<unsigned char> b;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0)
    b.insert(b.end(), block, block + in.gcount());
  if (in.bad()) throw Error(path + ": cannot be read: " + std::strerror(errno));
  return b;
}

// MAT v4: matrices one after the other, each a 20-byte header (type, rows, columns, imaginary
// flag, name length), the name and the data; the type's thousands digit gives the byte order.
void check_v4(const std::string &path, const std::vector<unsigned char> &b)
{
  std::size_t at = 0;
  while (at < b.size()) {
    std::string here = "the matrix at byte " + std::to_string(at);
    if (b.size() - at < 20)
      throw Error(path + ": damaged MAT file: " + here + " is cut inside its header");
    std::int32_t h[5];
    std::memcpy(h, &b[at], sizeof h);
    if (h[0] < 0 || h[0] >= 5000)  // not little-endian: big-endian (thousands digit 1)
      for (auto &v : h) {
        const auto u = static_cast<std::uint32_t>(v);
        v = static_cast<std::int32_t>((u >> 24) | ((u >> 8) & 0xff00u) | ((u << 8) & 0xff0000u) |
                                      (u << 24));
      }
    static const int sizes[] = {8, 4, 4, 2, 2, 1};
    const int precision = (h[0] / 10) % 10;
    if (h[0] < 0 || h[0] >= 5000 || precision > 5 || h[1] < 0 || h[2] < 0 || h[4] < 1)
      throw Error(path + ": damaged MAT file: " + here + " has an impossible header");
    const std::uint64_t need = 20 + static_cast<std::uint64_t>(h[4]) +
                               static_cast<std::uint64_t>(h[1]) * static_cast<std::uint64_t>(h[2]) *
                                   sizes[precision] * (h[3] ? 2 : 1);
    const std::size_t name_end = at + 20 + static_cast<std::size_t>(h[4]);
    if (name_end <= b.size()) {  // the name, up to its NUL
      const char *name = reinterpret_cast<const char *>(&b[at + 20]);
      here = "variable '" + std::string(name, ::strnlen(name, static_cast<std::size_t>(h[4]))) +
             "' at byte " + std::to_string(at);
    }
    if (need > b.size() - at)
      throw Error(path + ": damaged MAT file: " + here + " (" + std::to_string(h[1]) + "x" +
                  std::to_string(h[2]) + ") needs " + std::to_string(need) + " bytes, only " +
                  std::to_string(b.size() - at) + " are left (a cut or truncated file)");
    at += static_cast<std::size_t>(need);
  }
}

bool host_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

void check_mat_integrity(const std::string &path)
{
  // a file is opened several times per command (its variables, the signal, the rate, the
  // speed): checked once while it stays the same file, of the same size and time
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw Error(path + ": cannot open: " + std::strerror(errno));
  static std::set<std::tuple<dev_t, ino_t, off_t, time_t, long>> whole;
  const auto key =
      std::make_tuple(st.st_dev, st.st_ino, st.st_size, st.st_mtim.tv_sec, st.st_mtim.tv_nsec);
  if (whole.count(key)) return;
  const std::vector<unsigned char> b = slurp(path);
  const bool v5 = b.size() >= 128 && std::memcmp(b.data(), "MATLAB ", 7) == 0;
  if (!v5) {
    check_v4(path, b);
  } else {
    // bytes 124-125: the version (0x0100: v5, 0x0200: v7.3, an HDF5 file); 126-127 "IM" in the
    // writer's byte order: as read here, "IM" is little-endian
    const bool little = b[126] == 'I' && b[127] == 'M';
    const unsigned version = little ? b[124] | b[125] << 8 : b[125] | b[124] << 8;
    if (version != 0x0200)
      Checker(path, little != host_little_endian()).elements(b, 128, b.size(), "");
  }
  whole.insert(key);
}

}  // namespace ohmdem::post
