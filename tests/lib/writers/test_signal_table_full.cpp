// SPDX-License-Identifier: GPL-2.0-or-later
// The signal table writer on a full disk: a write that fails part-way leaves whole rows only
// (the file is cut back to its last whole row) and throws a message naming the file. The
// full disk is a file size limit (RLIMIT_FSIZE: write(2) stops at the limit as on a full file
// system, with EFBIG) and /dev/full (every write fails with ENOSPC).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "temp_dir.h"
#include "writers/npy_header.h"
#include "writers/signal_table.h"

using ohmdem::test::temp_path;

namespace {

// Lowers this process's file size limit for its lifetime (SIGXFSZ ignored: write() fails).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes)
  {
    ::getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lim = old_;
    lim.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &lim);
  }
  ~FileSizeLimit()
  {
    ::setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
};

std::string slurp(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ohmdem::SignalTable::Options options(const std::string &path, ohmdem::SignalTable::Format f)
{
  ohmdem::SignalTable::Options o;
  o.path = path;
  o.columns = {"time", "R"};
  o.format = f;
  return o;
}

// Writes rows until the limit stops the table; returns the message.
std::string fill(ohmdem::SignalTable &t)
{
  try {
    for (int i = 0; i < 100000; ++i) {
      const double row[2] = {i * 1e-6, 1.3912345678901234 + i * 1e-9};
      t.row(row);
    }
    t.flush();
  } catch (const std::runtime_error &e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SignalTableFull, TextKeepsWholeRowsAndNamesTheFile)
{
  const std::string path = temp_path("full.txt");
  std::string msg;
  {
    FileSizeLimit limit(10007);  // not a row boundary
    ohmdem::SignalTable t(options(path, ohmdem::SignalTable::Format::Text));
    msg = fill(t);
    EXPECT_TRUE(t.failed());
    t.flush();  // reported once: nothing more
  }
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("write failed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("last whole row"), std::string::npos) << msg;
  const std::string text = slurp(path);
  ASSERT_GT(text.size(), 1000u);
  EXPECT_LE(text.size(), 10007u);
  EXPECT_EQ(text.back(), '\n');  // no cut row
  // every row has its two values
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# time R");
  int rows = 0;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    double a = 0, b = 0;
    EXPECT_TRUE(ls >> a >> b) << line;
    EXPECT_DOUBLE_EQ(a, rows * 1e-6);
    ++rows;
  }
  EXPECT_GT(rows, 100);
}

TEST(SignalTableFull, NpyKeepsWholeRowsAndItsRowCount)
{
  const std::string path = temp_path("full.npy");
  std::string msg;
  {
    FileSizeLimit limit(20003);
    ohmdem::SignalTable t(options(path, ohmdem::SignalTable::Format::Npy));
    msg = fill(t);
  }
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  const std::uint64_t size = std::filesystem::file_size(path);
  // Continuing the file reads its header and rows: all whole, none dropped as cut.
  std::uint64_t kept = 0;
  EXPECT_EQ(ohmdem::truncate_npy_table(path, {"time", "R"}, 1e9, kept), 0u);
  EXPECT_GT(kept, 100u);
  EXPECT_EQ(std::filesystem::file_size(path), size);
  const std::string bytes = slurp(path);
  EXPECT_NE(bytes.find(ohmdem::npy_rows_field(kept) + ",)"), std::string::npos);
}

TEST(SignalTableFull, DevFullFailsNamingTheFile)
{
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  try {
    ohmdem::SignalTable t(options("/dev/full", ohmdem::SignalTable::Format::Text));
    const std::string msg = fill(t);
    EXPECT_NE(msg.find("'/dev/full'"), std::string::npos) << msg;
  } catch (const std::runtime_error &e) {  // the header's write already failed
    EXPECT_NE(std::string(e.what()).find("'/dev/full': write failed"), std::string::npos)
        << e.what();
  }
}
