// SPDX-License-Identifier: GPL-2.0-or-later
// `ohmdem-post collect` end to end: the collected table (values equal to `stats` / `diagnose` on
// the same window), skipped and bad runs, determinism; and the row selection of
// `plot --kind indicators --where` on its output.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "dsp/stats.h"
#include "io/json.h"
#include "io/read_table.h"
#include "io/run_folders.h"
#include "io/table_select.h"
#include "run_folder_fixtures.h"
#include "synth.h"
#include "temp_dir.h"
#include "test_util.h"

namespace ohmdem::post {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;
using test::make_run;
using test::make_sweep;

struct Outcome {
  int status = -1;
  std::string out, err;
};

// Runs ohmdem-post with `args` in the working directory `cwd`; stdout and stderr apart.
Outcome post(const std::string &args, const std::string &cwd = "")
{
  static int counter = 0;
  const std::string err_file = ohmdem::test::temp_dir().string() + "/collect_stderr_" +
                               std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string cmd = (cwd.empty() ? "" : "cd '" + cwd + "' && ") +
                          std::string(OHMDEM_POST_EXE) + " " + args + " 2>'" + err_file + "'";
  Outcome r;
  std::unique_ptr<FILE, int (*)(FILE *)> p(popen(cmd.c_str(), "r"), pclose);
  if (!p) return r;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p.get())) r.out.append(buf, n);
  const int st = pclose(p.release());
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  r.err = test::slurp(err_file);
  std::remove(err_file.c_str());
  // the ASan build: an error exit must not hide a sanitizer report
  EXPECT_EQ(r.err.find("Sanitizer"), std::string::npos) << args << "\n" << r.err;
  EXPECT_EQ(r.err.find("runtime error:"), std::string::npos) << args << "\n" << r.err;
  return r;
}

// Splits a CSV line (a quoted comma splits too: used on lines without one, or from the end).
std::vector<std::string> cells(const std::string &line)
{
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string c;
  while (std::getline(ss, c, ',')) out.push_back(c);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

std::vector<std::string> data_lines(const std::string &text)
{
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string line;
  while (std::getline(ss, line))
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

TEST(Collect, CsvRowsColumnsAndValues)
{
  const std::string root = make_sweep("csv");
  const Outcome r = post("collect --format csv fixed_10 fixed_2 force_1", root);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto lines = data_lines(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;  // header + 3 runs
  const std::vector<std::string> header = {
      "run",      "status",   "area",     "defect",        "depth",     "F",
      "load",     "resumed",  "size_deg", "t_sliding_end", "t_start_s", "t_end_s",
      "n",        "peak_ohm", "mean_ohm", "rms_ohm",       "std_ohm",   "skewness",
      "kurtosis", "crest",    "shape",    "impulse",       "clearance", "duty"};
  EXPECT_EQ(cells(lines[0]), header);
  // natural order of the folders; a string with a comma is quoted; missing keys are empty
  // (run.json without "status": an older run, counted as finished)
  EXPECT_EQ(
      lines[1].rfind("fixed_2,finished,\"greenwood, exact\",inner,,320,fixed,,2,0.002,0.002,", 0),
      0u)
      << lines[1];
  EXPECT_EQ(lines[2].rfind("fixed_10,finished,,inner,,320,fixed,,10,0.002,0.002,", 0), 0u)
      << lines[2];
  EXPECT_EQ(lines[3].rfind("force_1,finished,,outer,0.0001,,force,true,1,,0,", 0), 0u) << lines[3];
  // the duty is the fraction of samples with n_masked > 0 in the window
  const auto c2 = cells(lines[1]), c10 = cells(lines[2]), c1 = cells(lines[3]);
  EXPECT_EQ(c2.back(), "0.15");
  EXPECT_EQ(c10.back(), "0.3");
  EXPECT_EQ(c1.back(), "0.06");
  EXPECT_EQ(c10[12], "1800");  // t_sliding_end 2 ms skipped at 100 kHz
  EXPECT_EQ(c1[12], "2000");
  // metadata lines
  EXPECT_NE(r.out.find("# runs: 3 collected"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# non-scalar run.json keys left out: tags"), std::string::npos);
  EXPECT_EQ(r.out.find("skipped"), std::string::npos);

  // the file is readable back (read_table), e.g. by plot --kind indicators
  const Outcome o = post("collect --format csv --output collected.csv fixed_2 fixed_10", root);
  ASSERT_EQ(o.status, 0) << o.err;
  const ColumnTable t = read_table(root + "/collected.csv");
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_DOUBLE_EQ(t.columns[t.find("size_deg")][1], 10);
  EXPECT_EQ(t.text[t.find("run")][0], "fixed_2");
  EXPECT_EQ(t.text[t.find("area")][0], "greenwood, exact");  // quoted comma read back

  // --params and --varying
  const Outcome p = post("collect --format csv --params size_deg,load .", root);
  EXPECT_EQ(p.status, 1);  // the root itself is not a run, and it is not searched
  EXPECT_NE(p.err.find("(try --recursive)"), std::string::npos) << p.err;
  const Outcome pr = post("collect --format csv --recursive --params size_deg,load .", root);
  ASSERT_EQ(pr.status, 0) << pr.err;
  EXPECT_EQ(data_lines(pr.out)[0].rfind("run,status,size_deg,load,t_start_s,", 0), 0u) << pr.out;
  const Outcome v = post("collect --format csv --varying fixed_2 fixed_10", root);
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_EQ(data_lines(v.out)[0].rfind("run,status,area,size_deg,t_start_s,", 0), 0u) << v.out;
  const Outcome unknown = post("collect --params nope fixed_2", root);
  EXPECT_EQ(unknown.status, 1);
  EXPECT_NE(unknown.err.find("no run.json of the runs has the key 'nope'"), std::string::npos);
}

TEST(Collect, IndicatorsEqualStatsOnTheSameWindow)
{
  const std::string root = make_sweep("equal");
  const Outcome r = post("collect --format json --recursive .", root);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out, "collect output");
  const Json &rows = *j.find("rows");
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string run = rows[i].find("run")->string();
    const Json *from = rows[i].find("t_sliding_end");
    const std::string window = from->is_null() ? "" : " --from " + json_number(from->number());
    const Outcome s = post("stats --format json " + run + "/signal.txt" + window, root);
    ASSERT_EQ(s.status, 0) << s.err;
    const Json st = Json::parse(s.out, "stats output");
    for (const auto &f : indicator_fields()) {
      const std::string col = f.dimensionless ? f.key : std::string(f.key) + "_ohm";
      ASSERT_TRUE(rows[i].find(col)) << col;
      EXPECT_EQ(rows[i].find(col)->number(), st.find(f.key)->number()) << run << " " << col;
    }
    EXPECT_EQ(rows[i].find("n")->number(), st.find("n")->number());
    EXPECT_EQ(rows[i].find("t_start_s")->number(), st.find("t_start_s")->number());
    EXPECT_EQ(rows[i].find("t_end_s")->number(), st.find("t_end_s")->number());
  }
  // an explicit window applies to every run, and --column picks another column
  const Outcome w = post("collect --format json --from 0.005 --to 0.015 fixed_2", root);
  ASSERT_EQ(w.status, 0) << w.err;
  const Outcome ws = post("stats --format json --from 0.005 --to 0.015 fixed_2/signal.txt", root);
  const Json a = Json::parse(w.out), b = Json::parse(ws.out);
  EXPECT_EQ((*a.find("rows"))[0].find("kurtosis")->number(), b.find("kurtosis")->number());
  EXPECT_EQ((*a.find("rows"))[0].find("n")->number(), 1001);
  const Outcome k = post("collect --format json --keep-sliding fixed_2", root);
  ASSERT_EQ(k.status, 0) << k.err;
  EXPECT_EQ((*Json::parse(k.out).find("rows"))[0].find("n")->number(), 2000);
  const Outcome m = post("collect --format csv --column n_masked fixed_2", root);
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_NE(data_lines(m.out)[0].find(",peak,mean,"), std::string::npos) << m.out;  // no unit
}

TEST(Collect, FolderWithoutRunJsonIsSkippedWithAWarning)
{
  const std::string root = make_sweep("skip");
  const Outcome r = post("collect --format csv no_metadata fixed_2 figures", root);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("WARNING: collect: skipped no_metadata: no run.json"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("WARNING: collect: skipped figures: no signal.txt and no run.json"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("ERROR"), std::string::npos);
  EXPECT_NE(r.out.find("# folders skipped: 2: figures ("), std::string::npos) << r.out;
  EXPECT_EQ(data_lines(r.out).size(), 2u);
}

TEST(Collect, NoRunFolderIsAnError)
{
  const std::string root = make_sweep("none");
  const Outcome r = post("collect no_metadata figures does_not_exist", root);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.rfind("ERROR: collect: no run folder", 0), 0u) << r.err;  // no warnings
  EXPECT_NE(r.err.find("3 skipped; does_not_exist: does not exist; figures: no signal.txt and "
                       "no run.json"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("no_metadata: no run.json"), std::string::npos) << r.err;
  const Outcome rec = post("collect --recursive figures", root);
  EXPECT_EQ(rec.status, 1);
  EXPECT_NE(rec.err.find("ERROR: collect: no run folder"), std::string::npos) << rec.err;
}

TEST(Collect, BadSignalFailsNamingTheRunUnlessSkipped)
{
  const std::string root = make_sweep("bad");
  make_run(root + "/broken", R"({"size_deg": 4})", 2000, 40, 4, 1.39, 1500);
  make_run(root + "/empty", R"({"size_deg": 5})", 0);
  const Outcome r = post("collect --recursive --output out.csv .", root);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("ERROR: run broken: broken/signal.txt:1502: non-finite value (NaN)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(root + "/out.csv"));  // nothing written on failure
  const Outcome e = post("collect empty fixed_2", root);
  EXPECT_EQ(e.status, 1);
  EXPECT_NE(e.err.find("ERROR: run empty: empty/signal.txt: no data rows"), std::string::npos)
      << e.err;
  // a run.json of the wrong form is bad data of that run too
  std::ofstream(root + "/fixed_10/run.json") << "[1, 2]\n";
  const Outcome j = post("collect fixed_10", root);
  EXPECT_EQ(j.status, 1);
  EXPECT_NE(j.err.find("ERROR: run fixed_10: fixed_10/run.json: metadata must be a JSON object"),
            std::string::npos)
      << j.err;

  const Outcome s = post("collect --recursive --skip-bad --format csv .", root);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.err.find("WARNING: collect: skipped run broken: broken/signal.txt:1502"),
            std::string::npos)
      << s.err;
  EXPECT_NE(s.err.find("WARNING: collect: skipped run empty:"), std::string::npos) << s.err;
  EXPECT_NE(s.out.find("# bad runs skipped: 3: broken empty fixed_10"), std::string::npos) << s.out;
  EXPECT_EQ(data_lines(s.out).size(), 3u);  // header, fixed_2, force_1
  const Outcome all_bad = post("collect --skip-bad broken empty", root);
  EXPECT_EQ(all_bad.status, 1);
  EXPECT_NE(all_bad.err.find("ERROR: collect: none of the 2 run(s) has usable data"),
            std::string::npos)
      << all_bad.err;
}

TEST(Collect, UnfinishedRunsAreFlaggedOrSkipped)
{
  const std::string root = make_sweep("status");
  // the engine writes how a run ended; a run cut short has fewer samples
  make_run(root + "/stopped", R"({"size_deg": 3, "status": "interrupted", "time_reached": 0.0105})",
           1050);
  make_run(root + "/crashed", R"({"size_deg": 4, "status": "failed", "time_reached": 0.004})", 400);
  make_run(root + "/done", R"({"size_deg": 5, "status": "finished", "time_reached": 0.02})");
  // killed outright (SIGKILL, an MPI abort): the deck's "running" stays
  make_run(root + "/killed", R"({"size_deg": 6, "status": "running", "time_reached": 0})", 300);
  const Outcome r = post("collect --format json done stopped crashed fixed_2 killed", root);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("WARNING: collect: run stopped did not finish (run.json status "
                       "\"interrupted\", time reached 0.0105 s)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("WARNING: collect: run crashed did not finish (run.json status \"failed\""),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("run done"), std::string::npos) << r.err;
  const Json j = Json::parse(r.out, "collect output");
  const Json &rows = *j.find("rows");
  ASSERT_EQ(rows.size(), 5u);
  std::map<std::string, std::string> status;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    status[rows[i].find("run")->string()] = rows[i].find("status")->string();
    // how the run ended is a column, not a swept parameter
    EXPECT_EQ(rows[i].find("time_reached"), nullptr);
  }
  EXPECT_EQ(status["stopped"], "interrupted");
  EXPECT_EQ(status["crashed"], "failed");
  EXPECT_EQ(status["done"], "finished");
  EXPECT_EQ(status["fixed_2"], "finished");  // no "status": an older run, taken as finished
  EXPECT_EQ(status["killed"], "running");
  EXPECT_NE(r.out.find("3 run(s) did not finish"), std::string::npos) << r.out;

  const Outcome s = post("collect --skip-bad --format csv done stopped crashed fixed_2", root);
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_NE(s.err.find("WARNING: collect: skipped run stopped: did not finish"), std::string::npos)
      << s.err;
  EXPECT_NE(s.err.find("WARNING: collect: skipped run crashed: did not finish"), std::string::npos)
      << s.err;
  EXPECT_NE(s.out.find("# bad runs skipped: 2: crashed stopped"), std::string::npos) << s.out;
  const auto lines = data_lines(s.out);
  ASSERT_EQ(lines.size(), 3u) << s.out;  // header, fixed_2, done
  EXPECT_EQ(lines[1].rfind("done,finished,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[2].rfind("fixed_2,finished,", 0), 0u) << lines[2];

  std::ofstream(root + "/done/run.json") << R"({"status": "paused"})"
                                         << "\n";
  const Outcome bad = post("collect done", root);
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(
      bad.err.find("\"status\" must be \"running\", \"finished\", \"interrupted\" or \"failed\""),
      std::string::npos)
      << bad.err;
}

TEST(Collect, DeterministicAndIndependentOfArgumentOrder)
{
  const std::string root = make_sweep("determinism");
  for (const char *fmt : {"table", "csv", "json"}) {
    const std::string f = std::string(" --format ") + fmt;
    const Outcome a = post("collect" + f + " force_1 fixed_10 no_metadata fixed_2", root);
    const Outcome b = post("collect" + f + " force_1 fixed_10 no_metadata fixed_2", root);
    const Outcome c = post("collect" + f + " fixed_2 no_metadata fixed_10 force_1", root);
    ASSERT_EQ(a.status, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(a.out, c.out) << fmt;
    EXPECT_EQ(a.err, c.err);
  }
}

// Synthetic defect runs (the shape our engine writes at 1 MHz) with the diagnosis columns
// equal to `diagnose --format csv` on the same run.
TEST(Collect, DiagnosisColumnsEqualDiagnose)
{
  const std::string root = fresh_dir("diagnose");
  for (const char *kind : {"inner", "outer"}) {
    const std::string dir = root + "/" + kind;
    fs::create_directories(dir);
    test::DefectSpec spec;
    spec.kind = kind;
    spec.snr_db = 20;
    spec.duration = 0.08;
    const auto sig = test::defect_signal(bearing_preset("machado2014"), spec);
    std::ofstream out(dir + "/signal.txt");
    out << "# time R n_masked\n";
    char buf[128];
    for (std::size_t i = 0; i < 2000; ++i) {  // a sliding phase, skipped by t_sliding_end
      std::snprintf(buf, sizeof buf, "%.9g %.9g 0\n", i * 1e-6, 1.2 + 1e-4 * (i % 97));
      out << buf;
    }
    for (std::size_t i = 0; i < sig.signal.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.9g %.9g %d\n", (i + 2000) * 1e-6, sig.signal.x[i],
                    sig.signal.x[i] > 1.39 * 1.04 ? 1 : 0);
      out << buf;
    }
    std::ofstream(dir + "/run.json") << R"({"bearing": "machado2014", "omega_inner": 500, "defect": ")"
                                     << kind << R"(", "size_deg": 1, "t_sliding_end": 0.002})"
                                     << "\n";
  }
  const Outcome r = post("collect --diagnose --format csv inner outer", root);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lines = data_lines(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  const auto head = cells(lines[0]);
  const std::vector<std::string> tail(head.end() - 4, head.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"diag_defect", "diag_score", "diag_frequency_Hz",
                                            "diag_size_deg"}));
  for (std::size_t i = 1; i < 3; ++i) {
    const auto row = cells(lines[i]);
    const Outcome d = post("diagnose --format csv " + row[0] + "/signal.txt", root);
    ASSERT_EQ(d.status, 0) << d.err;
    const auto dl = data_lines(d.out);
    ASSERT_EQ(dl.size(), 2u);
    const auto dr = cells(dl[1]);  // defect, score, frequency_Hz, kinematic_Hz, size_deg, ...
    EXPECT_EQ(row[row.size() - 4], row[0]);  // the defect found is the one simulated
    EXPECT_EQ(row[row.size() - 4], dr[0]);
    EXPECT_EQ(row[row.size() - 3], dr[1]);
    EXPECT_EQ(row[row.size() - 2], dr[2]);
    EXPECT_EQ(row[row.size() - 1], dr[4]);
  }
  // without bearing or speed the run is bad
  std::ofstream(root + "/outer/run.json") << R"({"defect": "outer"})"
                                          << "\n";
  const Outcome nb = post("collect --diagnose outer", root);
  EXPECT_EQ(nb.status, 1);
  EXPECT_NE(nb.err.find("ERROR: run outer: --diagnose needs the bearing"), std::string::npos)
      << nb.err;
}

TEST(Collect, PlotIndicatorsOfTheCollectedCsv)
{
  if (!test::have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const std::string root = make_sweep("plot");
  make_run(root + "/fixed_5", R"({"size_deg": 5, "load": "fixed"})", 2000, 40, 8);
  make_run(root + "/healthy", R"({"load": "fixed"})", 2000, 40, 0);  // no size_deg
  const Outcome c = post("collect --recursive --format csv --output collected.csv .", root);
  ASSERT_EQ(c.status, 0) << c.err;
  const Outcome p = post(
      "plot --kind indicators --x size_deg --y kurtosis,crest --where load=fixed "
      "--output fixed.png collected.csv",
      root);
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_TRUE(test::is_png(root + "/fixed.png"));
  EXPECT_NE(p.out.find("1 row(s) without a value of size_deg left out"), std::string::npos)
      << p.out;
  const Outcome all =
      post("plot --kind indicators --x size_deg --y mean_ohm --output all.png collected.csv", root);
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_TRUE(test::is_png(root + "/all.png"));
  const Outcome none = post(
      "plot --kind indicators --x size_deg --y kurtosis --where load=free --output x.png "
      "collected.csv",
      root);
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.err.find("no row satisfies --where load=free"), std::string::npos) << none.err;
  const Outcome text =
      post("plot --kind indicators --x load --y kurtosis --output x.png collected.csv", root);
  EXPECT_EQ(text.status, 1);
  EXPECT_NE(text.err.find("column load is not numeric ('fixed')"), std::string::npos) << text.err;
}

}  // namespace
}  // namespace ohmdem::post
