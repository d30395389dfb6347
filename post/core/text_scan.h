// SPDX-License-Identifier: GPL-2.0-or-later
// Small text helpers shared by the readers: splitting, strict number parsing and the decimal
// resolution of a printed number (used to tell printing jitter from non-uniform sampling).
#ifndef OHMDEM_POST_TEXT_SCAN_H
#define OHMDEM_POST_TEXT_SCAN_H

#include <string>
#include <string_view>
#include <vector>

namespace ohmdem::post {

// Splits on blanks (space, tab, CR). Views point into `line`.
std::vector<std::string_view> split_blanks(std::string_view line);
void split_blanks(std::string_view line, std::vector<std::string_view> &out);

// The non-empty items of a comma-separated list ("a,,b," -> a, b), as option values give them.
std::vector<std::string> split_commas(const std::string &s);
std::string_view trim(std::string_view s);
bool starts_with(std::string_view s, std::string_view prefix);

// Parses the whole token as a double (a leading '+' is accepted; "nan"/"inf" parse to the
// non-finite values, so callers can report them). Returns false if the token is not a number.
bool parse_double(std::string_view token, double &value);

// Significant digits written in a number: "0.125" -> 3, "1.5e-05" -> 2, "0.003" -> 1.
int significant_digits(std::string_view token);
// Rounding step of numbers printed with `digits` significant digits (as printf %g does) whose
// largest magnitude is `max_abs`: 10^(floor(log10 max_abs) - digits + 1); 0 if max_abs is 0.
double print_resolution(double max_abs, int digits);

// Parses a value for a command-line option, naming the option in the error.
double parse_option_double(const std::string &option, const std::string &text);
long long parse_option_int(const std::string &option, const std::string &text);

}  // namespace ohmdem::post

#endif
