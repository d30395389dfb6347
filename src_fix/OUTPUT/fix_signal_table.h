// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix signal/table: global values of computes, fixes and variables
   written every N steps to a '#'-headed table, at full rate (buffered,
   shortest round-trip numbers, no re-parsing of variables from strings).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(signal/table,FixSignalTable)
// clang-format on

#else

#ifndef LMP_FIX_SIGNAL_TABLE_H
#define LMP_FIX_SIGNAL_TABLE_H

#include <memory>
#include <string>
#include <vector>

#include "fix.h"

namespace ohmdem {
class SignalTable;
}

namespace LAMMPS_NS {

class FixSignalTable : public Fix {
 public:
  FixSignalTable(class LAMMPS *, int, char **);
  ~FixSignalTable() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void post_run() override;
  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

 private:
  enum class Kind { Time, Step, Compute, Fix, Variable };
  struct Term {
    Kind kind;
    std::string id;  // compute, fix or variable ID
    int index = 0;   // 0: the scalar, k >= 1: element k of the global vector
    int slot = -1;   // position in modify's/variable's lists, resolved in init()
  };
  // A value is one reference or a sum of references (f_a[6]+f_b[6]): summed here rather
  // than through an equal-style variable, whose formula is parsed again at every evaluation.
  using Value = std::vector<Term>;

  void parse(int narg, char **arg);
  void open_table();
  void refuse_nan();  // stops the run when a value of the row is NaN
  double simulated_time();
  void resolve(Term &t);
  double evaluate(const Term &t);

  std::vector<Value> values_;
  std::vector<std::string> columns_;
  std::vector<std::string> values_text_;  // each value as written in the command
  std::vector<double> row_;
  std::string path_;
  enum class Append { Auto, Yes, No } append_ = Append::Auto;
  enum class Format { Auto, Text, Npy } format_ = Format::Auto;  // Auto: from the extension
  double flush_seconds_ = 1.0;

  // The simulated time, kept by the fix so that it survives restarts and changes of dt.
  double time_ = 0.0;     // the time of the reference step
  bigint time_step_ = 0;  // the reference step
  double dt_ref_ = 0.0;   // the step length since the reference
  bool restored_ = false;
  double restored_time_ = 0.0;

  bool opened_ = false;
  std::unique_ptr<ohmdem::SignalTable> table_;  // process 0 only
};

}  // namespace LAMMPS_NS

#endif
#endif
