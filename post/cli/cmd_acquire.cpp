// SPDX-License-Identifier: GPL-2.0-or-later
// ohmdem-post acquire: what an instrument records of a signal (sensitivity, anti-alias filter,
// sampling, noise, ADC), written as a '#'-headed "time value" table the other commands read.
#include <cmath>
#include <iostream>
#include <optional>

#include "cli/commands.h"
#include "cli/common.h"
#include "core/error.h"
#include "core/text_scan.h"
#include "dsp/acquire.h"
#include "report/acquire_report.h"

namespace ohmdem {
const char *version();
}

namespace ohmdem::post::cli {

namespace {

AcquireSettings settings(const Args &a)
{
  AcquireSettings s;
  s.scale = a.number("--scale", 1);
  s.offset = a.number("--offset", 0);
  if (a.has("--lowpass"))
    s.lowpass = a.number_in("--lowpass", 0, Range::above(0), "a cut-off", "Hz");
  s.order = static_cast<int>(a.integer_in("--order", 4, 1, kMaxButterworthOrder, "a filter order"));
  if (a.has("--order") && !a.has("--lowpass")) throw Error("option --order needs --lowpass HZ");
  s.steady_start = a.choice("--filter-start", {"steady", "zero"}) == "steady";
  if (a.has("--rate")) s.rate = a.number_in("--rate", 0, Range::above(0), "a rate", "Hz");
  if (a.has("--noise-rms") && a.has("--noise-density"))
    throw Error("give the noise once: --noise-rms or --noise-density");
  s.noise_rms = a.number_in("--noise-rms", 0, Range::at_least(0), "a value");
  s.noise_density = a.number_in("--noise-density", 0, Range::at_least(0), "a value");
  if (a.has("--input-referred")) {
    if (!a.has("--noise-rms") && !a.has("--noise-density"))
      throw Error("option --input-referred needs --noise-rms or --noise-density");
    s.noise_rms *= std::abs(s.scale);
    s.noise_density *= std::abs(s.scale);
  }
  s.seed = static_cast<std::uint64_t>(a.integer_in("--seed", 1, 0));
  if (a.has("--bits") != a.has("--range"))
    throw Error(a.has("--bits") ? "option --bits needs --range LO HI (the ADC's input range)"
                                : "option --range needs --bits N (the ADC's resolution)");
  if (a.has("--bits")) {
    s.bits = static_cast<int>(a.integer_in("--bits", 0, 1, 32));
    const auto r = a.values("--range");
    s.lo = parse_option_double("--range", r[0]);
    s.hi = parse_option_double("--range", r[1]);
    if (!(s.lo < s.hi))
      throw Error("option --range expects LO < HI, got " + r[0] + " " + r[1] +
                  " (an empty ADC range)");
  }
  return s;
}

// A value column's name: one word, not 'time' (the time column's).
std::string column_name(const Args &a, const std::string &option, const std::string &input_name)
{
  const std::string name = a.has(option) ? a.get(option) : input_name;
  if (name.empty() || name.find_first_of(" \t\r\n,#\"") != std::string::npos)
    throw Error("option " + option +
                " expects one word without blanks, commas, quotes or '#', got '" + name + "'");
  if (name == "time")
    throw Error("the value column cannot be called 'time' (the time column's name): give " +
                option);
  return name;
}

// The options of acquire (run_acquire parses them).
void declare_options(Args &a)
{
  add_input_options(a, "--input-rate");
  a.section("Measurement chain");
  a.option("--scale", "K",
           "sensitivity: output = K * input + offset (e.g. the injected current in A to turn "
           "R in ohm into volts; an accelerometer's V/(m/s^2))",
           "1");
  a.option("--offset", "X", "added after the scale (output unit)", "0");
  a.option("--lowpass", "HZ",
           "anti-alias Butterworth low-pass cut-off (-3 dB), below the output Nyquist rate/2");
  a.option("--order", "N", "order of the low-pass (1..20)", "4");
  a.option("--filter-start", "HOW",
           "filter state at the first sample: steady (as if the first value had lasted "
           "forever: no start-up transient) | zero (as scipy's sosfilt)",
           "steady");
  a.option("--rate", "HZ", "the instrument's sampling rate (default: the input's)");
  a.option("--noise-rms", "X", "white noise rms per sample (output unit)");
  a.option("--noise-density", "X",
           "white noise density (output unit per sqrt(Hz)); rms = X sqrt(rate/2)");
  a.flag("--input-referred",
         "the noise is given in the input's unit (a datasheet's noise density): times |scale|");
  a.option("--seed", "N", "seed of the noise (same seed, same record)", "1");
  a.option("--bits", "N", "ADC resolution (1..32); needs --range");
  a.option("--range", "LO HI", "ADC input range (output unit); needs --bits", "", 2);
  a.option("--across-column", "NAME",
           "the sensor's second axis, another column or MAT variable of FILE (e.g. acc_across "
           "beside acc_along): through the same chain with its own noise (seed N + 1), written "
           "as a third column; diagnose reads it with --across-column");
  a.section("Output");
  a.option("--name", "NAME", "name of the value column (default: the input column's)");
  a.option("--across-name", "NAME",
           "name of the second axis's column (default: its input column's)");
  a.option("--format", "FMT", "table ('# time NAME' header, blank-separated) | csv", "table");
  a.option("--output", "FILE", "write to FILE instead of standard output");
  a.option("--unit", "UNIT", "unit of the output, written in the metadata");
}

}  // namespace

int run_acquire(const std::vector<std::string> &argv)
{
  Args a("acquire", "[options] FILE",
         "What an instrument records of the signal, written as a '#'-headed 'time value' table\n"
         "(or CSV) that the other commands read. The chain, in this order, every step optional:\n"
         "  1. column, then output = scale * input + offset (the sensor's sensitivity);\n"
         "  2. anti-alias Butterworth low-pass (--lowpass), run at the input rate;\n"
         "  3. sampling at --rate: every k-th sample when the rate divides the input rate,\n"
         "     else cubic interpolation of the filtered signal at the instrument's times;\n"
         "  4. white Gaussian noise added to each sample (the front end's noise at the ADC\n"
         "     input): --noise-rms per sample, or --noise-density D over the output band\n"
         "     0..rate/2, i.e. rms = D sqrt(rate/2);\n"
         "  5. ADC: codes at LO + k q, q = (HI-LO)/2^bits, k = 0..2^bits-1, nearest code\n"
         "     (mid-tread, ties up), values beyond the codes clipped (with a warning).\n"
         "The time column keeps the input's clock. No option: a copy of the column.");
  declare_options(a);
  if (!a.parse(argv, std::cout)) return 0;
  const AcquireSettings set = settings(a);
  const RunMetadata meta = run_metadata(a);
  const Signal s = load_input(a, meta, 4, false, "--input-rate");
  const std::string name = column_name(a, "--name", s.name);
  const Acquisition q = acquire(s, set);
  // the second axis: the same chain, its own noise
  std::optional<Acquisition> q2;
  std::string name2;
  if (a.has("--across-column")) {
    InputOptions io = input_options(a, "--input-rate");
    io.column = a.get("--across-column");
    io.min_samples = 4;
    const Signal s2 = load_companion(
        io, meta, s,
        {"acquire", "--across-column " + io.column, "signal", "name the sensor's second axis"},
        "--input-rate");
    name2 = column_name(a, "--across-name", s2.name);
    if (name2 == name)
      throw Error("acquire: the two columns are both called '" + name +
                  "': give --name or --across-name");
    AcquireSettings set2 = set;
    set2.seed = set.seed + 1;
    q2 = acquire(s2, set2);
  } else if (a.has("--across-name")) {
    throw Error("acquire: --across-name needs --across-column (it names that column)");
  }
  Output out(a);
  if (out.format() == OutputFormat::Json)
    throw Error("option --format expects table|csv for acquire (the other commands read them)");
  for (const auto &w : q.warnings) std::cerr << "WARNING: acquire: " << flag_named(w) << "\n";
  if (q2)
    for (const auto &w : q2->warnings)
      std::cerr << "WARNING: acquire: " << name2 << ": " << flag_named(w) << "\n";

  AcquisitionContext c;
  c.input_rate = s.rate;
  c.rate_given = a.has("--rate");
  c.input_referred = a.has("--input-referred");
  c.unit = a.get("--unit");
  out.stream() << acquisition_head(ohmdem::version(), s.meta)
               << flag_named(acquisition_chain(set, q, c));
  if (q2)
    out.stream() << "# second axis: " << name2 << " (input " << a.get("--across-column")
                 << "), the same chain, noise seed " << set.seed + 1 << ", clipped " << q2->clipped
                 << " of " << q2->signal.size() << "\n";
  out.stream() << acquisition_table(q.signal, name, q2 ? &q2->signal : nullptr, name2,
                                    out.format() == OutputFormat::Csv);
  return 0;  // a failed write is reported once, with its reason (Output, standard output)
}

}  // namespace ohmdem::post::cli
