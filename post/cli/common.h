// SPDX-License-Identifier: GPL-2.0-or-later
// Options shared by several commands: input selection, output format, bearing and speed.
#ifndef OHMDEM_POST_CLI_COMMON_H
#define OHMDEM_POST_CLI_COMMON_H

#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bearing/bearing.h"
#include "cli/args.h"
#include "cli/setting_flags.h"
#include "core/pending_file.h"
#include "dsp/envelope.h"
#include "io/load_signal.h"
#include "io/run_metadata.h"
#include "report/report.h"

namespace ohmdem::post::cli {

// `rate_option` names the option giving the rate of a signal without time stamps (acquire uses
// --rate for the instrument's rate and --input-rate for this).
void add_input_options(Args &a, const std::string &rate_option = "--rate");
InputOptions input_options(const Args &a, const std::string &rate_option = "--rate");
// --metadata FILE, else run.json next to the first input (unless --no-metadata), else none.
RunMetadata run_metadata(const Args &a);
// load_signal, with the settings in its messages and time base named by the flags: `rate_option`
// for the input's rate ("uniform, --rate"), the others as every command names them.
Signal load_named(const InputOptions &o, const RunMetadata &meta,
                  const std::string &rate_option = "--rate");
// A second channel recorded with signal `s` (another column or file, loaded with `io`): refused
// unless it holds s's rate and number of samples, and when it holds s's own samples. The
// messages begin "<command>: <what> holds", name s "the <record>", and end with `name_it`.
struct CompanionNames {
  std::string command, what, record, name_it;
};
Signal load_companion(const InputOptions &io, const RunMetadata &meta, const Signal &s,
                      const CompanionNames &n, const std::string &rate_option = "--rate");
// Loads the signal and applies the metadata's t_sliding_end as default --from when asked.
Signal load_input(const Args &a, const RunMetadata &meta, std::size_t min_samples,
                  bool skip_sliding_phase = false, const std::string &rate_option = "--rate");

void add_output_options(Args &a);
// The --output files whose writing failed (a full disk), each as its message ("writing 'F'
// failed: No space left on device; no file is left"): the command line exits non-zero with
// them (commands.cpp), after the command has returned.
std::vector<std::string> &failed_outputs();
// The files a command reads: its inputs, the value of every option given but `output` (the
// option naming the file written) that names a file (--metadata, --log, --baseline, ...), the
// run.json beside its first input, and `more`.
std::vector<std::string> input_files(const Args &a, const std::string &output = "--output",
                                     const std::vector<std::string> &more = {});
// Refuses `output` (the value of `option`) when it is one of `inputs` (the same file, by device
// and inode: a link or another path to it too): writing it would destroy the record.
void refuse_input_as_output(const std::string &option, const std::string &output,
                            const std::vector<std::string> &inputs);
class Output {
 public:
  // --output FILE (refused when it is one of input_files(a, more_inputs)) or stdout; --format
  // The file is written under a temporary name and renamed onto FILE when whole
  // (core/pending_file.h): a failed write leaves no file, or the former one unchanged.
  explicit Output(const Args &a, const std::vector<std::string> &more_inputs = {});
  ~Output();  // finishes the file and notes a failed write in failed_outputs()
  Output(const Output &) = delete;
  Output &operator=(const Output &) = delete;
  std::ostream &stream() { return file_ ? file_->stream() : *out_; }
  OutputFormat format() const { return format_; }
  void write(const Result &r) { write_result(stream(), r, format_); }

 private:
  std::unique_ptr<PendingStream> file_;
  std::string path_;
  std::ostream *out_;
  OutputFormat format_;
  int unwinding_;  // exceptions in flight when made: more at its end means the command failed
};

void add_bearing_options(Args &a);
struct BearingChoice {
  std::optional<BearingGeometry> geometry;
  std::optional<double> fr;  // shaft frequency (Hz)
  std::string geometry_source, fr_source;
};
// Command line first (--bearing NAME from the catalog --catalog DIR, --nb/--db/--dp/--beta,
// --rpm/--shaft-hz/--omega), then the run's metadata (its nb, db, dp: what ran).
BearingChoice bearing_choice(const Args &a, const RunMetadata &meta);

// Options several commands share, one range each (doc/ohmdem-post.md, "Common ranges").
constexpr long long kMaxHarmonics = 50;  // the diagnosis comb's limit; labels and plots agree
int harmonics_option(const Args &a, long long fallback);  // --harmonics N, 1..kMaxHarmonics
int levels_option(const Args &a);                         // --levels N (kurtogram), 0..16
std::size_t peaks_option(const Args &a);                  // --peaks N, 0..100000
double tolerance_option(const Args &a);                   // --tolerance F, (0, 0.2), 0.02
Band band_option(const Args &a);                          // --band F1 F2, 0 <= F1 < F2 (Hz)

// Unit of a quantity named as in our signal.txt ("R" -> "ohm"); --unit overrides; "" if unknown.
std::string unit_of(const Args &a, const std::string &quantity);

}  // namespace ohmdem::post::cli

#endif
