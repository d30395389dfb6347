// SPDX-License-Identifier: GPL-2.0-or-later
// Command-line options of one ohmdem-post command: declared with their help text, parsed
// strictly (an unknown option or a missing value is an error naming it), printed by --help.
#ifndef OHMDEM_POST_CLI_ARGS_H
#define OHMDEM_POST_CLI_ARGS_H

#include <climits>
#include <cmath>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace ohmdem::post::cli {

// The values a numeric option accepts, as its error message shows them ("> 0", "in (0, 0.5)").
struct Range {
  double lo = -INFINITY, hi = INFINITY;
  bool lo_open = false, hi_open = false;
  static Range above(double lo) { return {lo, INFINITY, true, false}; }
  static Range at_least(double lo) { return {lo, INFINITY, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  bool contains(double v) const;
  std::string text() const;  // "> 0", ">= 0", "in (0, 0.5)", "in [0, 1]"
};

class Args {
 public:
  Args(std::string command, std::string synopsis, std::string description);

  // An option taking `arity` values (metavar names them in --help); default shown in --help.
  void option(const std::string &name, const std::string &metavar, const std::string &help,
              const std::string &def = "", int arity = 1);
  void flag(const std::string &name, const std::string &help);
  void section(const std::string &title);  // a heading in --help
  // An option no longer taken: given, it is refused with `instead` (what to use), not as unknown
  void retired(const std::string &name, const std::string &instead);

  // Returns false when --help was given (help already printed to `out`).
  bool parse(const std::vector<std::string> &argv, std::ostream &out);
  void print_help(std::ostream &out) const;

  bool has(const std::string &name) const;
  std::string get(const std::string &name) const;  // the given value, else the default
  std::vector<std::string> values(const std::string &name) const;  // for arity > 1
  double number(const std::string &name, double fallback = NAN) const;
  long long integer(const std::string &name, long long fallback) const;
  // Ranged values: the option's value (else the fallback) checked against lo..hi; out of range
  // is an error naming the option, the expected form and the value ("option --order expects a
  // filter order in 1..20, got 0"). `what` names the value, `unit` follows the bounds.
  long long integer_in(const std::string &name, long long fallback, long long lo,
                       long long hi = LLONG_MAX, const std::string &what = "an integer") const;
  double number_in(const std::string &name, double fallback, const Range &range,
                   const std::string &what = "a number", const std::string &unit = "") const;
  // One of the words in `choices` ("peaks|bins|envelope"), else an error listing them.
  std::string choice(const std::string &name, const std::vector<std::string> &choices) const;
  const std::vector<std::string> &positional() const { return positional_; }
  // every value of every option given but `except`
  std::vector<std::string> given_values(const std::string &except = "") const;
  const std::string &command() const { return command_; }

 private:
  struct Spec {
    std::string name, metavar, help, def;
    int arity = 0;  // 0 = flag
  };
  const Spec *spec(const std::string &name) const;

  std::string command_, synopsis_, description_;
  std::vector<Spec> specs_;  // in declaration order, sections as specs with empty name
  std::map<std::string, std::vector<std::string>> given_;
  std::map<std::string, std::string> retired_;
  std::vector<std::string> positional_;
};

}  // namespace ohmdem::post::cli

#endif
