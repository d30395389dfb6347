// SPDX-License-Identifier: GPL-2.0-or-later
// The files around a run, without a shell (run_folder.h).
#include "writers/run_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace ohmdem {

namespace {

std::string why(int err)
{
  return std::strerror(err);
}

}  // namespace

std::string check_folder_path(const std::string &path)
{
  if (path.empty()) return "the folder name is empty";
  if (path.size() + kRunFileNameRoom >= PATH_MAX)
    return "the path '" + path.substr(0, 60) + "...' has " + std::to_string(path.size()) +
           " characters: a folder of a run takes at most " +
           std::to_string(PATH_MAX - kRunFileNameRoom - 1) +
           " (PATH_MAX = " + std::to_string(PATH_MAX) + ", less room for the file names)";
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    if (end - start > NAME_MAX)
      return "the path '" + path.substr(0, 60) + "...' has a component of " +
             std::to_string(end - start) + " characters ('" + path.substr(start, 20) +
             "...'): a file name takes at most NAME_MAX = " + std::to_string(NAME_MAX);
    start = end + 1;
  }
  return "";
}

std::string make_folders(const std::string &path)
{
  const std::string bad = check_folder_path(path);
  if (!bad.empty()) return "cannot create the folder: " + bad;
  // Each prefix ending before a '/', then the whole path.
  for (std::size_t pos = 1; pos <= path.size(); ++pos) {
    if (pos < path.size() && path[pos] != '/') continue;
    const std::string part = path.substr(0, pos);
    if (::mkdir(part.c_str(), 0777) == 0) continue;
    const int err = errno;
    struct stat st {};
    if (err == EEXIST && ::stat(part.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) continue;
    if (err == EEXIST)
      return "cannot create the folder " + path + ": " + part + " exists and is not a folder";
    return "cannot create the folder " + path + ": " + part + ": " + why(err);
  }
  return "";
}

std::string copy_file(const std::string &from, const std::string &to)
{
  std::ifstream in(from, std::ios::binary);
  if (!in) return "cannot read " + from + ": " + why(errno);
  const std::string tmp = to + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write " + tmp + ": " + why(errno);
    out << in.rdbuf();
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      return "cannot write " + tmp + " (a full disk?)";
    }
  }
  if (std::rename(tmp.c_str(), to.c_str()) != 0) {
    const int err = errno;
    std::remove(tmp.c_str());
    return "cannot replace " + to + ": " + why(err);
  }
  return "";
}

std::string replace_file(const std::string &path, const std::string &text)
{
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return "cannot write " + path + ": " + why(errno);
  std::size_t done = 0;
  int err = 0;
  while (done < text.size() && err == 0) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      err = n < 0 ? errno : ENOSPC;
    else
      done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(tmp.c_str(), path.c_str()) != 0) err = errno;
  if (err == 0) return "";
  ::unlink(tmp.c_str());
  return "cannot write " + path + ": " + why(err) + " (the previous file, if any, is kept)";
}

namespace {

// The header of LIGGGHTS 3.8's write_restart: flag (int), then the value; flags 0..48 in
// order, -1 ends it. The kinds of the values (read_restart.cpp's enum, checked on a file the
// deck wrote, tests/lib/writers/test_run_folder.cpp).
enum Kind { kText, kInt, kBig, kDouble };
Kind header_kind(int flag)
{
  if (flag == 0 || flag == 4 || flag == 22) return kText;  // version, units, atom style
  if (flag == 5 || flag == 23 || flag == 25 || flag == 28 || flag == 31 || flag == 34)
    return kBig;                   // step, atoms, bonds, angles, dihedrals, impropers
  if (flag >= 37) return kDouble;  // box bounds, special factors, tilts
  return kInt;
}
constexpr int kLastHeaderFlag = 48;

struct Bytes {
  const std::string &data;
  std::size_t pos = 0;
  bool take(void *to, std::size_t n)
  {
    if (data.size() - pos < n) return false;
    std::memcpy(to, data.data() + pos, n);
    pos += n;
    return true;
  }
};

// Where each per-process chunk of atoms starts, walking back from the end: a chunk is an int
// N, then N doubles, each atom's values starting with their count, then x, y, z. "" when the
// data after byte FROM ends in exactly NCHUNKS chunks; their atoms are added to `atoms`, and
// `from` is set to where the first chunk starts. Each atom must lie in the box `box` (xlo xhi
// ylo yhi zlo zhi) with every value a finite number: a damaged atom section is refused here
// (read_restart would lose the atom, or its contacts, with a stock message).
std::string check_atom_chunks(const std::string &data, std::size_t &from, int nchunks,
                              const double *box, long long &atoms)
{
  std::size_t end = data.size();
  std::string misplaced;
  for (int c = 0; c < nchunks; ++c) {
    // The longest chunk first (an empty one, N = 0, only when nothing longer fits): a short
    // false match inside the doubles is then never taken for the chunk.
    bool found = false;
    const std::size_t longest = (end - from) < 4 ? 0 : (end - from - 4) / 8;
    for (std::size_t k = 0; k <= longest && !found && end - from >= 4; ++k) {
      const std::size_t n = longest - k;
      const std::size_t start = end - 4 - 8 * n;
      int stored = -1;
      std::memcpy(&stored, data.data() + start, 4);
      if (stored < 0 || static_cast<std::size_t>(stored) != n) continue;
      // The atoms inside: each count a whole number >= 1 that ends inside the chunk.
      long long count = 0;
      std::size_t m = 0;
      bool whole = true;
      std::string where;
      while (m < n && whole) {
        double size = 0;
        std::memcpy(&size, data.data() + start + 4 + 8 * m, 8);
        whole = size >= 4 && size <= static_cast<double>(n - m) &&
                size == static_cast<double>(static_cast<std::size_t>(size));
        if (!whole) break;
        for (std::size_t v = 1; v < static_cast<std::size_t>(size) && where.empty(); ++v) {
          double value = 0;
          std::memcpy(&value, data.data() + start + 4 + 8 * (m + v), 8);
          if (!std::isfinite(value))
            where = "atom " + std::to_string(count + 1) + " has a value that is not a number";
          else if (v <= 3 && (value < box[2 * (v - 1)] || value > box[2 * v - 1]))
            where = "atom " + std::to_string(count + 1) + " lies outside the box (" + "xyz"[v - 1] +
                    " = " + std::to_string(value) + ")";
        }
        m += static_cast<std::size_t>(size), ++count;
      }
      if (!whole || m != n) continue;
      found = true;
      atoms += count;
      end = start;
      if (misplaced.empty()) misplaced = where;
    }
    if (!found) return "its atoms are cut (no whole section of atoms ends the file)";
  }
  if (!misplaced.empty()) return "its atoms are damaged: " + misplaced;
  from = end;
  return "";
}

// The fixes' sections that end the part before the atoms: -1 (the end of the force fields),
// the number of fixes, each fix's ID, style, the byte count of its state and the state, then
// the number of per-atom fixes, each with ID, style and its values per atom. Strings are an
// int length (with the NUL) and the characters. True when they end exactly at END.
bool fix_sections_end_at(const std::string &data, std::size_t p, std::size_t end)
{
  Bytes b{data, p};
  int marker = 0, nfix = 0;
  auto text = [&b, &data]() {
    int n = 0;
    if (!b.take(&n, 4) || n < 1 || n > 4096 || data.size() - b.pos < static_cast<std::size_t>(n))
      return false;
    b.pos += static_cast<std::size_t>(n);
    return data[b.pos - 1] == '\0';
  };
  if (!b.take(&marker, 4) || marker != -1 || !b.take(&nfix, 4) || nfix < 0 || nfix > 10000)
    return false;
  for (int i = 0; i < nfix; ++i) {
    int size = 0;
    if (!text() || !text() || !b.take(&size, 4) || size < 0 ||
        data.size() - b.pos < static_cast<std::size_t>(size))
      return false;
    b.pos += static_cast<std::size_t>(size);
  }
  int nperatom = 0;
  if (!b.take(&nperatom, 4) || nperatom < 0 || nperatom > 10000) return false;
  for (int i = 0; i < nperatom; ++i) {
    int values = 0;
    if (!text() || !text() || !b.take(&values, 4) || values < 0) return false;
  }
  return b.pos == end;
}

std::string read_whole(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

namespace {

// check_restart_file, and where the fixes' sections start in the data read (`fixes_at`, with
// the data in `kept`; npos when the file was too large to read back).
std::string check_restart(const std::string &path, std::string *kept, std::size_t *fixes_at)
{
  if (fixes_at) *fixes_at = std::string::npos;
  // A multi-file restart (write_restart FILE.%): FILE.base holds the header and the fixes,
  // FILE.0 ... FILE.(P-1) each process's atoms.
  const std::size_t percent = path.find('%');
  const std::string base =
      percent == std::string::npos ? path : std::string(path).replace(percent, 1, "base");
  struct stat st {};
  if (::stat(base.c_str(), &st) != 0) return "no file " + base + " (" + why(errno) + ")";
  if (!S_ISREG(st.st_mode)) return base + " is not a file";
  if (st.st_size > (1LL << 28))  // larger files: LIGGGHTS reads them as they are
    return "";
  const std::string data = read_whole(base);
  const std::string bad = "the restart file " + base + " (" + std::to_string(data.size()) +
                          " bytes) is damaged or not a LIGGGHTS restart file: ";
  Bytes b{data};
  int flag = 0, expected = 0, nprocs = 0;
  long long natoms = -1;
  double box[6] = {0, 0, 0, 0, 0, 0};
  for (;; ++expected) {
    if (!b.take(&flag, 4)) return bad + "its header is cut";
    if (flag == -1 && expected == kLastHeaderFlag + 1) break;
    if (flag != expected)
      return bad + "header entry " + std::to_string(expected) + " has the flag " +
             std::to_string(flag);
    const Kind kind = header_kind(flag);
    if (kind == kText) {
      int n = 0;
      if (!b.take(&n, 4) || n < 1 || n > 4096 || data.size() - b.pos < static_cast<std::size_t>(n))
        return bad + "its header is cut";
      if (flag == 0 && data.compare(b.pos, 16, "Version LIGGGHTS") != 0)
        return bad + "it does not start with a LIGGGHTS version";
      b.pos += static_cast<std::size_t>(n);
    } else {
      long long value = 0;
      double real = 0;
      int small = 0;
      const bool ok = kind == kInt   ? b.take(&small, 4)
                      : kind == kBig ? b.take(&value, 8)
                                     : b.take(&real, 8);
      if (!ok) return bad + "its header is cut";
      if (flag == 7) nprocs = small;
      if (flag == 23) natoms = value;
      if (flag >= 37 && flag <= 42) box[flag - 37] = real;  // box lo/hi in x, y, z
    }
  }
  if (nprocs < 1 || natoms < 0) return bad + "its header gives no processes or atoms";
  // The atoms: after the fixes in this file, or in one file per process.
  long long atoms = 0;
  std::size_t atoms_start = data.size();
  if (percent == std::string::npos) {
    atoms_start = b.pos;
    const std::string cut = check_atom_chunks(data, atoms_start, nprocs, box, atoms);
    if (!cut.empty()) return bad + cut;
  } else {
    for (int p = 0; p < nprocs; ++p) {
      const std::string part = std::string(path).replace(percent, 1, std::to_string(p));
      if (::stat(part.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return bad + "the file of process " + std::to_string(p) + ", " + part + ", is missing";
      std::size_t from = 0;
      const std::string cut = check_atom_chunks(read_whole(part), from, 1, box, atoms);
      if (!cut.empty()) return bad + "in " + part + ", " + cut;
    }
  }
  if (atoms != natoms)
    return bad + "it holds " + std::to_string(atoms) + " atoms, its header says " +
           std::to_string(natoms);
  // Between the header and the atoms: the types and force fields (their layout is the
  // styles'), then the fixes' sections, which must end exactly where the atoms start.
  bool fixes = false;
  std::size_t p = b.pos;
  for (; p + 12 <= atoms_start && !fixes; ++p) fixes = fix_sections_end_at(data, p, atoms_start);
  if (!fixes)
    return bad + "its fixes' sections are damaged (they do not end where the atoms start)";
  if (fixes_at) *fixes_at = p - 1;
  if (kept) *kept = data;
  return "";
}

}  // namespace

std::string check_restart_file(const std::string &path)
{
  return check_restart(path, nullptr, nullptr);
}

std::string restart_fix_state(const std::string &path, const std::string &style, std::string &state,
                              bool &found)
{
  found = false;
  state.clear();
  std::string data;
  std::size_t at = std::string::npos;
  const std::string bad = check_restart(path, &data, &at);
  if (!bad.empty() || at == std::string::npos) return bad;
  // -1, the number of fixes, then each fix's ID, style, state size and state
  Bytes b{data, at + 4};
  int nfix = 0;
  b.take(&nfix, 4);
  auto text = [&b, &data]() {
    int n = 0;
    b.take(&n, 4);
    const std::string t = data.substr(b.pos, static_cast<std::size_t>(n) - 1);  // less its NUL
    b.pos += static_cast<std::size_t>(n);
    return t;
  };
  for (int i = 0; i < nfix; ++i) {
    text();  // the ID
    const std::string fix_style = text();
    int size = 0;
    b.take(&size, 4);
    if (fix_style == style && !found) {
      state = data.substr(b.pos, static_cast<std::size_t>(size));
      found = true;
    }
    b.pos += static_cast<std::size_t>(size);
  }
  return "";
}

std::string lock_path(const std::string &folder)
{
  return folder + "/.ohmdem.lock";
}

LockAnswer lock_folder(const std::string &folder, long pid, const std::string &host,
                       const std::function<bool(long)> &alive, double wait_seconds)
{
  const std::string file = lock_path(folder);
  const std::string mine = "pid " + std::to_string(pid) + " host " + host + "\n";
  LockAnswer answer;
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const bool ok = ::write(fd, mine.data(), mine.size()) == static_cast<ssize_t>(mine.size());
      ::close(fd);
      if (!ok) answer.error = "cannot write the lock " + file;
      return answer;
    }
    if (errno != EEXIST) {
      answer.error = "cannot create the lock " + file + ": " + why(errno);
      return answer;
    }
    std::ifstream in(file);
    std::string word_pid, word_host, holder_host;
    long holder = -1;
    in >> word_pid >> holder >> word_host >> holder_host;
    const bool readable = word_pid == "pid" && word_host == "host" && holder > 0;
    if (readable && holder == pid && holder_host == host) return answer;  // ours already
    if (readable && holder_host != host) {
      // Its pid means nothing here: a lock from another host is never judged stale.
      answer.error = "the output folder " + folder + " is in use by the run of pid " +
                     std::to_string(holder) + " on host " + holder_host + " (" + file +
                     "; a lock from another host is not judged stale: its process cannot be "
                     "checked from " +
                     host + "); give another -var out, or remove " + file +
                     " when that run has ended";
      return answer;
    }
    if (readable && alive(holder)) {
      double waited = 0;
      while (waited < wait_seconds && alive(holder)) {
        ::usleep(100000);
        waited += 0.1;
      }
      if (!alive(holder)) {
        --attempt;  // it ended while we waited: its lock is stale now
        continue;
      }
      char how_long[64] = "";
      if (wait_seconds > 0)
        std::snprintf(how_long, sizeof how_long, ", still running after %g s", wait_seconds);
      answer.error = "the output folder " + folder + " is in use by the live run of pid " +
                     std::to_string(holder) + " on this host (" + host + ", " + file + how_long +
                     "): give another -var out, or wait for that run to end (a run just "
                     "stopped may take a moment to end: run again in a few seconds)";
      return answer;
    }
    // Stale (its process has ended) or unreadable (cut while written): replace it.
    answer.note = "removed the stale lock " + file +
                  (readable ? " of pid " + std::to_string(holder) + ", which no longer runs"
                            : " (unreadable)");
    std::remove(file.c_str());
  }
  answer.error = "cannot take the lock " + file + ": another run took it at the same time";
  return answer;
}

bool locked_by_another(const std::string &folder, long pid, const std::string &host)
{
  std::ifstream in(lock_path(folder));
  if (!in) return false;
  std::string word_pid, word_host, holder_host;
  long holder = -1;
  in >> word_pid >> holder >> word_host >> holder_host;
  return word_pid == "pid" && word_host == "host" && !(holder == pid && holder_host == host);
}

void unlock_folder(const std::string &folder, long pid, const std::string &host)
{
  const std::string file = lock_path(folder);
  std::ifstream in(file);
  std::string word_pid, word_host, holder_host;
  long holder = -1;
  in >> word_pid >> holder >> word_host >> holder_host;
  if (holder == pid && holder_host == host) std::remove(file.c_str());
}

namespace {
// The turns this process holds: folder -> the descriptor that holds the flock.
std::map<std::string, int> &held_turns()
{
  static std::map<std::string, int> turns;
  return turns;
}
}  // namespace

std::string hold_turn(const std::string &folder)
{
  if (held_turns().count(folder)) return "";  // already this process's turn
  const std::string file = folder + "/.ohmdem.turn";
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return "cannot open the turn file " + file + ": " + why(errno);
  int rc = 0;
  while ((rc = ::flock(fd, LOCK_EX)) != 0 && errno == EINTR) {
  }
  if (rc != 0) {
    const std::string message = "cannot take the turn " + file + ": " + why(errno);
    ::close(fd);
    return message;
  }
  held_turns()[folder] = fd;
  return "";
}

void release_turn(const std::string &folder)
{
  const auto it = held_turns().find(folder);
  if (it == held_turns().end()) return;
  ::flock(it->second, LOCK_UN);
  ::close(it->second);
  held_turns().erase(it);
}

}  // namespace ohmdem
