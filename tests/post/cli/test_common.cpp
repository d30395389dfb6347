// SPDX-License-Identifier: GPL-2.0-or-later
// The commands' shared input (post/cli/common.h): standard input, a pipe and a FIFO read like
// the file; endless or binary input fails with bounded memory.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli_run.h"
#include "io/json.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

using test::CliRun;
using test::run;
using test::shell;

// The data lines of a CSV report (the '#' metadata name the source, which differs).
std::string csv_rows(const std::string &out)
{
  std::string rows, line;
  std::istringstream ss(out);
  while (std::getline(ss, line))
    if (line.empty() || line[0] != '#') rows += line + "\n";
  return rows;
}

// A signal.txt longer than a pipe's buffer (64 KiB) and than the reader's chunk, so that input
// read twice or only partly gives other numbers.
std::string big_signal()
{
  const std::string path = ohmdem::test::temp_dir().string() + "/stdin_signal.txt";
  std::ofstream out(path);
  out << "# time R\n";
  char buf[64];
  for (int i = 0; i < 20000; ++i) {
    std::snprintf(buf, sizeof buf, "%.9g %.9g\n", i * 1e-5, 1.39 + 0.01 * ((i * 7919) % 101));
    out << buf;
  }
  return path;
}

TEST(Cli, StandardInputPipeAndFifoReadLikeTheFile)
{
  const std::string sig = big_signal();
  const std::string exe = OHMDEM_POST_EXE;
  const CliRun file = run("stats --format csv " + sig);
  ASSERT_EQ(file.status, 0) << file.out;
  const std::string want = csv_rows(file.out);
  EXPECT_NE(want.find(",20000,"), std::string::npos) << want;  // every row read
  const std::string commands[] = {
      exe + " stats --format csv - < " + sig,                         // '-': a file on stdin
      "cat " + sig + " | " + exe + " stats --format csv -",           // '-': a pipe
      "cat " + sig + " | " + exe + " stats --format csv /dev/stdin",  // read once, not twice
  };
  for (const auto &c : commands) {
    const CliRun r = shell(c);
    EXPECT_EQ(r.status, 0) << c << "\n" << r.out;
    EXPECT_EQ(csv_rows(r.out), want) << c;
  }
  const CliRun named = run("stats --format csv - < " + sig);
  EXPECT_NE(named.out.find("# source: standard input"), std::string::npos) << named.out;
  // a FIFO (named pipe): the writer runs in the background
  const std::string fifo = ohmdem::test::temp_dir().string() + "/signal.fifo";
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const CliRun f =
      shell(exe + " stats --format csv " + fifo + " & cat " + sig + " > " + fifo + "; wait");
  EXPECT_EQ(csv_rows(f.out), want);
  std::remove(fifo.c_str());
  // standard input is read once: given twice it is an error, not an empty second read
  const CliRun twice = run("stats --log - - < " + sig);
  EXPECT_EQ(twice.status, 1);
  EXPECT_NE(twice.out.find("standard input ('-') can be read only once"), std::string::npos)
      << twice.out;
}

TEST(Cli, EndlessOrBinaryInputFailsWithBoundedMemory)
{
  // /dev/zero never ends: the NUL byte stops it at once; a file without a line break stops at
  // the line limit (1 MiB) instead of growing one line
  const CliRun z = run("stats /dev/zero --rate 10");
  EXPECT_EQ(z.status, 1);
  EXPECT_NE(z.out.find("ERROR: /dev/zero:1: binary data (NUL byte)"), std::string::npos) << z.out;
  const std::string p = test::write_temp("one_long_line.txt", std::string(1100000, '5'));
  const CliRun l = run("stats " + p + " --rate 10");
  EXPECT_EQ(l.status, 1);
  EXPECT_NE(l.out.find("one_long_line.txt:1: line longer than 1048576 bytes"), std::string::npos)
      << l.out;
}

}  // namespace
}  // namespace ohmdem::post
