// SPDX-License-Identifier: GPL-2.0-or-later
// MATLAB .mat records (v5, and v7.3 when libmatio is built with HDF5, as Debian's is) through
// libmatio: real numeric vectors (double, single, integer classes) as doubles, with errors that
// name the variables present. Used by load_signal for the format "mat" and `.mat` files.
#ifndef OHMDEM_POST_READ_MAT_H
#define OHMDEM_POST_READ_MAT_H

#include <string>
#include <utility>
#include <vector>

namespace ohmdem::post {

// True when the file starts with a MAT-file text header ("MATLAB 5.0 MAT-file",
// "MATLAB 7.3 MAT-file"); false for a missing or shorter file.
bool has_mat_header(const std::string &path);

// True for a name ending in ".mat" (any case).
bool has_mat_extension(const std::string &path);

struct MatVariableInfo {
  std::string name;
  std::string kind;  // "double", "single", "int16", ..., "char", "struct", "cell", ...
  std::vector<std::size_t> dims;
  bool complex = false;
  bool numeric() const;       // a real double/single/integer array
  std::string shape() const;  // "122136x1 double"
};

// The variables of a MAT file, in file order. Throws Error for a file libmatio cannot open as
// MAT v4/v5/v7.3, or a damaged one (io/mat_integrity.h: every reader here checks it).
std::vector<MatVariableInfo> mat_variables(const std::string &path);

// The values of a real numeric vector (1xN or Nx1; a 1x1 is a vector of one) as doubles.
// Errors name the file and variable: missing (listing the variables), complex, struct/cell/char,
// more than one non-singleton dimension, empty, NaN/Inf.
std::vector<double> read_mat_vector(const std::string &path, const std::string &variable);

// A scalar (a 1x1 numeric variable, or a vector whose values are all equal, as a recorded speed
// or sampling rate), e.g. CWRU's `RPM`.
double read_mat_scalar(const std::string &path, const std::string &variable);

// The default signal of a file: the only numeric vector with more than one element; else a
// SettingError listing the variables ("choose the signal with {input.variable} NAME").
std::string default_mat_variable(const std::string &path);

// One signal of a MAT file for load_signal: `variable` (empty: default_mat_variable), sampled at
// `rate` Hz or, if rate <= 0, at the value of `rate_variable`; neither is an error (MAT files
// carry no time base).
struct MatSignal {
  std::vector<double> x;
  double rate = 0;
  std::string name;
  std::vector<std::pair<std::string, std::string>> meta;  // column, format, time base
};
MatSignal read_mat_signal(const std::vector<std::string> &files, const std::string &variable,
                          double rate, const std::string &rate_variable);

// "DE_time (122136x1 double), FE_time (122136x1 double), RPM (1x1 uint16)"
std::string mat_variable_list(const std::vector<MatVariableInfo> &vars);

}  // namespace ohmdem::post

#endif
