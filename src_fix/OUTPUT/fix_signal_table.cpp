// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   ohmdem - fix signal/table. The table itself (formatting, buffering, continuing
   a file after a restart) is plain C++ in signal_table.{h,cpp}; this file parses,
   resolves the values, evaluates them every N steps and keeps the time.
------------------------------------------------------------------------- */

#include "OUTPUT/fix_signal_table.h"

#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "comm.h"
#include "compute.h"
#include "error.h"
#include "input.h"
#include "modify.h"
#include "support/args.h"
#include "support/global_restart.h"
#include "update.h"
#include "variable.h"
#include "writers/signal_table.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// "c_ID[3]" -> {"ID", 3}; "c_ID" -> {"ID", 0}; index < 0 when the brackets are malformed.
std::pair<std::string, int> split_reference(const std::string &s)
{
  const auto open = s.find('[');
  if (open == std::string::npos) return {s.substr(2), 0};
  if (s.back() != ']' || open + 2 >= s.size()) return {s.substr(2, open - 2), -1};
  const std::string num = s.substr(open + 1, s.size() - open - 2);
  char *end = nullptr;
  const long k = std::strtol(num.c_str(), &end, 10);
  if (*end != '\0' || k < 1 || k > 1000000) return {s.substr(2, open - 2), -1};
  return {s.substr(2, open - 2), static_cast<int>(k)};
}

bool is_value(const char *w)
{
  return !std::strcmp(w, "time") || !std::strcmp(w, "step") || !std::strncmp(w, "c_", 2) ||
         !std::strncmp(w, "f_", 2) || !std::strncmp(w, "v_", 2);
}
}  // namespace

FixSignalTable::FixSignalTable(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  parse(narg, arg);
  restart_global = 1;
  scalar_flag = 1;  // the simulated time, for decks that count the steps left to run
  global_freq = 1;
  extscalar = 0;
  // The values are computed on the steps this fix writes: tell the computes.
  modify->addstep_compute_all((update->ntimestep / nevery) * nevery + nevery);
  time_ = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  time_step_ = update->ntimestep;
  dt_ref_ = update->dt;
}

FixSignalTable::~FixSignalTable() = default;

void FixSignalTable::parse(int narg, char **arg)
{
  ohmdem::StyleArgs a(error, "fix signal/table", narg, arg, 3);
  nevery = a.integer("N", "the output interval N, a number of steps >= 1", 1, 1 << 30);
  const char *forms =
      "time, step, c_ID, c_ID[I], f_ID, f_ID[I], v_name (I >= 1), or a sum of "
      "c_/f_/v_ references joined by + without blanks";
  while (!a.done() && is_value(a.peek())) {
    const std::string w = a.word("value", "a value");
    Value value;
    std::size_t start = 0;
    while (start <= w.size()) {
      const std::size_t plus = w.find('+', start);
      const std::string part = w.substr(start, plus == std::string::npos ? plus : plus - start);
      start = plus == std::string::npos ? w.size() + 1 : plus + 1;
      Term t;
      if (part == "time" || part == "step") {
        if (w != part) a.fail("value", forms, w.c_str());  // no sums of the time
        t.kind = part == "time" ? Kind::Time : Kind::Step;
      } else if (is_value(part.c_str())) {
        t.kind = part[0] == 'c' ? Kind::Compute : part[0] == 'f' ? Kind::Fix : Kind::Variable;
        const auto [id, index] = split_reference(part);
        if (index < 0 || id.empty() || (t.kind == Kind::Variable && index != 0))
          a.fail("value", forms, w.c_str());
        t.id = id;
        t.index = index;
      } else {
        a.fail("value", forms, w.c_str());
      }
      value.push_back(t);
    }
    values_.push_back(value);
    columns_.push_back(w);
    values_text_.push_back(w);
  }
  bool have_file = false;
  while (!a.done()) {
    const std::string kw = a.word("keyword", "a keyword");
    if (kw == "file") {
      path_ = a.word(kw, "the output file name");
      have_file = true;
    } else if (kw == "columns") {
      for (auto &c : columns_) {
        c = a.word(kw, "one column name per value (" + std::to_string(values_.size()) + ")");
        if (c.find_first_of(" \t#") != std::string::npos)
          a.fail(kw, "column names without blanks or '#'", c.c_str());
      }
    } else if (kw == "append") {
      const std::string w = a.word(kw, "yes, no or auto");
      if (w == "yes")
        append_ = Append::Yes;
      else if (w == "no")
        append_ = Append::No;
      else if (w == "auto")
        append_ = Append::Auto;
      else
        a.fail(kw, "yes, no or auto", w.c_str());
    } else if (kw == "format") {
      const std::string w = a.word(kw, "text (or txt) or npy");
      if (w == "text" || w == "txt")
        format_ = Format::Text;
      else if (w == "npy")
        format_ = Format::Npy;
      else
        a.fail(kw, "text (or txt) or npy", w.c_str());
    } else if (kw == "flush") {
      flush_seconds_ = a.non_negative(kw, "the longest wall time between two flushes, >= 0 (s)");
    } else {
      a.fail("keyword", "file, columns, append, format or flush (values come before the keywords)",
             kw.c_str());
    }
  }
  if (!have_file) a.fail("file", "an output file: the keyword is required", "nothing");
  // Without the keyword the file name decides: NAME.npy is binary, anything else text.
  if (format_ == Format::Auto)
    format_ = path_.size() > 4 && path_.compare(path_.size() - 4, 4, ".npy") == 0 ? Format::Npy
                                                                                  : Format::Text;
  row_.resize(values_.size());
}

int FixSignalTable::setmask()
{
  return END_OF_STEP;
}

void FixSignalTable::init()
{
  // Resolved again at each run: computes, fixes and variables may have been redefined.
  for (auto &value : values_)
    for (auto &t : value) resolve(t);
}

void FixSignalTable::resolve(Term &t)
{
  auto fail = [this](const std::string &msg) {
    error->all(FLERR, ("fix signal/table: " + msg).c_str());
  };
  const std::string element = "global vector element " + std::to_string(t.index);
  if (t.kind == Kind::Compute) {
    t.slot = modify->find_compute(t.id.c_str());
    if (t.slot < 0) fail("no compute with ID '" + t.id + "'");
    Compute *c = modify->compute[t.slot];
    if (t.index == 0 && !c->scalar_flag)
      fail("compute '" + t.id + "' has no global scalar: use c_ID[I] for its vector");
    if (t.index > 0 && (!c->vector_flag || t.index > c->size_vector))
      fail("compute '" + t.id + "' has no " + element);
  } else if (t.kind == Kind::Fix) {
    t.slot = modify->find_fix(t.id.c_str());
    if (t.slot < 0) fail("no fix with ID '" + t.id + "'");
    Fix *f = modify->fix[t.slot];
    if (t.index == 0 && !f->scalar_flag)
      fail("fix '" + t.id + "' has no global scalar: use f_ID[I] for its vector");
    if (t.index > 0 && (!f->vector_flag || t.index > f->size_vector))
      fail("fix '" + t.id + "' has no " + element);
    if (nevery % f->global_freq)
      fail("fix '" + t.id + "' is not computed every " + std::to_string(nevery) +
           " steps (its frequency: " + std::to_string(f->global_freq) + ")");
  } else if (t.kind == Kind::Variable) {
    t.slot = input->variable->find(const_cast<char *>(t.id.c_str()));
    if (t.slot < 0) fail("no variable '" + t.id + "'");
    if (!input->variable->equalstyle(t.slot))
      fail("variable '" + t.id + "' is not an equal-style variable");
  }
}

// Opened at the first run, after restart() may have restored the time: a continued run
// appends to the file of the first part (dropping rows written after the restart point).
void FixSignalTable::open_table()
{
  const bool append = append_ == Append::Yes || (append_ == Append::Auto && restored_);
  std::string msg;
  if (comm->me == 0) {
    ohmdem::SignalTable::Options o;
    o.path = path_;
    o.columns = columns_;
    o.append = append;
    o.format = format_ == Format::Npy ? ohmdem::SignalTable::Format::Npy
                                      : ohmdem::SignalTable::Format::Text;
    // Rows at or after the restart point are dropped; without a time column none are.
    o.resume_from = values_.front().front().kind == Kind::Time
                        ? restored_time_ + 0.5 * update->dt
                        : std::numeric_limits<double>::infinity();
    o.flush_seconds = flush_seconds_;
    try {
      table_ = std::make_unique<ohmdem::SignalTable>(o);
      if (table_->rows_dropped())
        error->warning(FLERR,
                       ("fix signal/table: dropped " + std::to_string(table_->rows_dropped()) +
                        " rows of '" + path_ + "' written after the restart point")
                           .c_str());
    } catch (const std::exception &e) {
      msg = e.what();
    }
  }
  int n = static_cast<int>(msg.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  if (n) {
    msg.resize(n);
    MPI_Bcast(msg.data(), n, MPI_CHAR, 0, world);
    error->all(FLERR, ("fix signal/table: " + msg).c_str());
  }
}

void FixSignalTable::setup(int)
{
  if (opened_) return;
  open_table();  // collective: every process learns whether process 0 could open the file
  opened_ = true;
}

double FixSignalTable::simulated_time()
{
  // dt is constant within a run: the time of a step is that of a reference step plus a whole
  // number of steps (one product, no sum of increments: no drift, and a run split by a
  // restart gives the single run's bits). When dt has changed since the reference (between
  // runs, or on restart), the reference moves to the current step at the old dt first.
  if (update->dt != dt_ref_) {
    time_ += (update->ntimestep - time_step_) * dt_ref_;
    time_step_ = update->ntimestep;
    dt_ref_ = update->dt;
  }
  return time_ + (update->ntimestep - time_step_) * update->dt;
}

double FixSignalTable::compute_scalar()
{
  return simulated_time();
}

double FixSignalTable::evaluate(const Term &v)
{
  switch (v.kind) {
    case Kind::Time:
      return simulated_time();
    case Kind::Step:
      return static_cast<double>(update->ntimestep);
    case Kind::Compute: {
      Compute *c = modify->compute[v.slot];
      if (v.index == 0) {
        if (!(c->invoked_flag & INVOKED_SCALAR)) {
          c->compute_scalar();
          c->invoked_flag |= INVOKED_SCALAR;
        }
        return c->scalar;
      }
      if (!(c->invoked_flag & INVOKED_VECTOR)) {
        c->compute_vector();
        c->invoked_flag |= INVOKED_VECTOR;
      }
      return c->vector[v.index - 1];
    }
    case Kind::Fix: {
      Fix *f = modify->fix[v.slot];
      return v.index == 0 ? f->compute_scalar() : f->compute_vector(v.index - 1);
    }
    case Kind::Variable:
      return input->variable->compute_equal(v.slot);
  }
  return 0.0;
}

void FixSignalTable::end_of_step()
{
  // Every process evaluates (computes may reduce over processes); process 0 writes.
  modify->clearstep_compute();
  for (std::size_t i = 0; i < values_.size(); ++i) {
    double sum = evaluate(values_[i].front());  // a single value keeps its bits (-0 too)
    for (std::size_t k = 1; k < values_[i].size(); ++k) sum += evaluate(values_[i][k]);
    row_[i] = sum;
  }
  modify->addstep_compute(update->ntimestep + nevery);
  refuse_nan();
  if (table_) {
    try {
      table_->row(row_.data());
    } catch (const std::exception &e) {
      error->one(FLERR, ("fix signal/table: " + std::string(e.what())).c_str());
    }
  }
}

// A NaN is never written into the signal: the run stops naming the column (R = inf, no
// conducting path, is a value; NaN is the arithmetic of inputs outside the laws' range).
// The values are global, the same on every process; the check is reduced all the same, so
// that every process stops together.
void FixSignalTable::refuse_nan()
{
  int bad = -1;
  for (std::size_t i = 0; i < row_.size() && bad < 0; ++i)
    if (std::isnan(row_[i])) bad = static_cast<int>(i);
  if (comm->nprocs > 1) {
    int any = -1;
    MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, world);
    bad = any;
  }
  if (bad < 0) return;
  char when[96];
  std::snprintf(when, sizeof when, "t = %.9g s (step " BIGINT_FORMAT ")", simulated_time(),
                update->ntimestep);
  const std::string what = columns_[bad] == values_text_[bad]
                               ? "'" + columns_[bad] + "'"
                               : "'" + columns_[bad] + "' (" + values_text_[bad] + ")";
  error->all(FLERR, ("fix signal/table: column " + what + " is not a number (NaN) at " + when +
                     ": the row is not written (the rows before it are kept); check the inputs "
                     "of what the column reads against their ranges")
                        .c_str());
}

void FixSignalTable::post_run()
{
  if (!table_) return;
  try {
    table_->flush();
  } catch (const std::exception &e) {
    // One process writes: error->one; ohmdem records the failure in run.json before the abort.
    error->one(FLERR, ("fix signal/table: " + std::string(e.what())).c_str());
  }
}

void FixSignalTable::write_restart(FILE *fp)
{
  // The rows up to the restart point go out with the restart file: a run killed later and
  // continued from this file leaves no gap in the table.
  if (table_) {
    try {
      table_->flush();
    } catch (const std::exception &e) {
      error->one(FLERR, ("fix signal/table: " + std::string(e.what())).c_str());
    }
  }
  ohmdem::RestartWriter record;
  record(time_, time_step_, dt_ref_, simulated_time());
  record.write(comm->me, fp);
}

void FixSignalTable::restart(char *buf)
{
  // The time reference and its dt: the steps after the restart point may run with another.
  ohmdem::RestartReader record(buf);
  record(time_, time_step_, dt_ref_, restored_time_);
  restored_ = true;
}

double FixSignalTable::memory_usage()
{
  return static_cast<double>(row_.capacity() * sizeof(double)) + (table_ ? 1 << 20 : 0);
}
