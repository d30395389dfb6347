// SPDX-License-Identifier: GPL-2.0-or-later
#include "io/read_mat.h"

#include <matio.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>

#include "core/error.h"
#include "core/sampled_signal.h"
#include "io/mat_integrity.h"

namespace ohmdem::post {

namespace {

// libmatio reports problems through a log function (by default on stderr); keep its last
// message for our error instead.
std::string &last_matio_message()
{
  static std::string m;
  return m;
}

void capture_log(int /*level*/, char *message)
{
  last_matio_message() = message ? message : "";
}

struct MatCloser {
  void operator()(mat_t *m) const { Mat_Close(m); }
};
struct VarFreer {
  void operator()(matvar_t *v) const { Mat_VarFree(v); }
};
using MatFile = std::unique_ptr<mat_t, MatCloser>;
using MatVar = std::unique_ptr<matvar_t, VarFreer>;

MatFile open_mat(const std::string &path)
{
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw Error(path + ": cannot open: " + std::strerror(errno));
  }
  static const bool log_set = [] {
    Mat_LogInitFunc("ohmdem-post", capture_log);
    return true;
  }();
  (void)log_set;
  last_matio_message().clear();
  MatFile f(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!f) {
    std::string why = has_mat_header(path)
                          ? "a MAT-file header, but libmatio cannot read it"
                          : "not a MATLAB MAT-file (no 'MATLAB 5.0/7.3 MAT-file' header)";
    if (!last_matio_message().empty()) why += " (libmatio: " + last_matio_message() + ")";
    throw Error(path + ": " + why);
  }
  // libmatio reads a cut variable's missing part as zeros and a damaged compressed one as what
  // zlib made of it: the file's structure and checksums are checked first
  check_mat_integrity(path);
  return f;
}

const char *class_name(matio_classes c)
{
  switch (c) {
    case MAT_C_EMPTY:
      return "empty";
    case MAT_C_CELL:
      return "cell";
    case MAT_C_STRUCT:
      return "struct";
    case MAT_C_OBJECT:
      return "object";
    case MAT_C_CHAR:
      return "char";
    case MAT_C_SPARSE:
      return "sparse";
    case MAT_C_DOUBLE:
      return "double";
    case MAT_C_SINGLE:
      return "single";
    case MAT_C_INT8:
      return "int8";
    case MAT_C_UINT8:
      return "uint8";
    case MAT_C_INT16:
      return "int16";
    case MAT_C_UINT16:
      return "uint16";
    case MAT_C_INT32:
      return "int32";
    case MAT_C_UINT32:
      return "uint32";
    case MAT_C_INT64:
      return "int64";
    case MAT_C_UINT64:
      return "uint64";
    case MAT_C_FUNCTION:
      return "function";
    case MAT_C_OPAQUE:
      return "opaque";
  }
  return "unknown";
}

MatVariableInfo info_of(const matvar_t &v)
{
  MatVariableInfo i;
  i.name = v.name ? v.name : "";
  i.kind = class_name(v.class_type);
  if (v.isLogical) i.kind = "logical";
  i.complex = v.isComplex != 0;
  for (int d = 0; d < v.rank; ++d) i.dims.push_back(v.dims[d]);
  return i;
}

template <class T>
void convert(const void *data, std::size_t n, std::vector<double> &out)
{
  const T *p = static_cast<const T *>(data);
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<double>(p[i]);
}

}  // namespace

bool MatVariableInfo::numeric() const
{
  static const char *kinds[] = {"double", "single", "int8",  "uint8",  "int16",  "uint16",
                                "int32",  "uint32", "int64", "uint64", "logical"};
  return !complex &&
         std::any_of(std::begin(kinds), std::end(kinds), [&](const char *k) { return kind == k; });
}

std::string MatVariableInfo::shape() const
{
  std::string s;
  for (std::size_t d : dims) s += (s.empty() ? "" : "x") + std::to_string(d);
  return s + " " + (complex ? "complex " : "") + kind;
}

bool has_mat_header(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  char head[19] = {};
  if (!in.read(head, sizeof head)) return false;
  const std::string h(head, sizeof head);
  return h.rfind("MATLAB ", 0) == 0 && h.find("MAT-file") != std::string::npos;
}

bool has_mat_extension(const std::string &path)
{
  if (path.size() < 4) return false;
  std::string e = path.substr(path.size() - 4);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ".mat";
}

std::vector<MatVariableInfo> mat_variables(const std::string &path)
{
  MatFile f = open_mat(path);
  std::vector<MatVariableInfo> vars;
  while (MatVar v{Mat_VarReadNextInfo(f.get())}) vars.push_back(info_of(*v));
  return vars;
}

std::string mat_variable_list(const std::vector<MatVariableInfo> &vars)
{
  std::string s;
  for (const auto &v : vars) s += (s.empty() ? "" : ", ") + v.name + " (" + v.shape() + ")";
  return s.empty() ? "none" : s;
}

std::vector<double> read_mat_vector(const std::string &path, const std::string &variable)
{
  MatFile f = open_mat(path);
  const std::string where = path + ": variable '" + variable + "'";
  MatVar info{Mat_VarReadInfo(f.get(), variable.c_str())};
  if (!info)
    throw Error(where + " not found (variables: " + mat_variable_list(mat_variables(path)) + ")");
  const MatVariableInfo i = info_of(*info);
  if (!i.numeric())
    throw Error(where + " is " + i.shape() +
                "; expected a real numeric vector (double, single or integer)");
  std::size_t n = 1, long_dims = 0;
  for (std::size_t d : i.dims) {
    n *= d;
    long_dims += d > 1;
  }
  if (long_dims > 1)
    throw Error(where + " is a " + i.shape() + " matrix; expected a vector (1xN or Nx1)");
  if (n == 0) throw Error(where + " is empty");
  info.reset();
  Mat_Rewind(f.get());
  MatVar v{Mat_VarRead(f.get(), variable.c_str())};
  if (!v || !v->data)
    throw Error(where + ": libmatio could not read the data" +
                (last_matio_message().empty() ? "" : " (" + last_matio_message() + ")"));
  std::vector<double> out;
  switch (v->class_type) {
    case MAT_C_DOUBLE:
      convert<double>(v->data, n, out);
      break;
    case MAT_C_SINGLE:
      convert<float>(v->data, n, out);
      break;
    case MAT_C_INT8:
      convert<std::int8_t>(v->data, n, out);
      break;
    case MAT_C_UINT8:
      convert<std::uint8_t>(v->data, n, out);
      break;
    case MAT_C_INT16:
      convert<std::int16_t>(v->data, n, out);
      break;
    case MAT_C_UINT16:
      convert<std::uint16_t>(v->data, n, out);
      break;
    case MAT_C_INT32:
      convert<std::int32_t>(v->data, n, out);
      break;
    case MAT_C_UINT32:
      convert<std::uint32_t>(v->data, n, out);
      break;
    case MAT_C_INT64:
      convert<std::int64_t>(v->data, n, out);
      break;
    case MAT_C_UINT64:
      convert<std::uint64_t>(v->data, n, out);
      break;
    default:
      throw Error(where + " is " + i.shape() + "; expected a real numeric vector");
  }
  if (static_cast<std::size_t>(v->data_size) * n > v->nbytes && v->nbytes > 0)
    throw Error(where + ": truncated data");
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(out[k]))
      throw Error(where + ": element " + std::to_string(k + 1) + " is a non-finite value (" +
                  (std::isnan(out[k]) ? "NaN" : "Inf") + ")");
  return out;
}

double read_mat_scalar(const std::string &path, const std::string &variable)
{
  const std::vector<double> v = read_mat_vector(path, variable);
  for (double x : v)
    if (x != v.front())
      throw Error(path + ": variable '" + variable + "' holds " + std::to_string(v.size()) +
                  " different values; expected a single number");
  return v.front();
}

std::string default_mat_variable(const std::string &path)
{
  const auto vars = mat_variables(path);
  std::vector<std::string> candidates;
  for (const auto &v : vars) {
    std::size_t n = 1, long_dims = 0;
    for (std::size_t d : v.dims) {
      n *= d;
      long_dims += d > 1;
    }
    if (v.numeric() && n > 1 && long_dims == 1) candidates.push_back(v.name);
  }
  if (candidates.size() == 1) return candidates.front();
  throw SettingError(
      path + ": " + std::to_string(candidates.size()) +
      " vector variables; choose the signal with {input.variable} NAME (variables: " +
      mat_variable_list(vars) + ")");
}

MatSignal read_mat_signal(const std::vector<std::string> &files, const std::string &variable,
                          double rate, const std::string &rate_variable)
{
  if (files.size() != 1)
    throw Error("MAT files are read one at a time, got " + std::to_string(files.size()) + " files");
  const std::string &path = files.front();
  MatSignal s;
  s.name = variable.empty() ? default_mat_variable(path) : variable;
  s.x = read_mat_vector(path, s.name);
  std::string base = "uniform, {input.rate}";
  if (rate > 0) {
    s.rate = rate;
  } else if (!rate_variable.empty()) {
    s.rate = read_mat_scalar(path, rate_variable);
    if (!(s.rate > 0))
      throw SettingError(path + ": variable '" + rate_variable + "' ({input.rate_variable}) is " +
                         format_number(s.rate) + "; a sampling rate must be > 0 Hz");
    base = "uniform, variable " + rate_variable + " (Hz)";
  } else {
    throw SettingError(
        path +
        ": a MAT file has no time base; pass {input.rate} HZ (or {input.rate_variable} NAME)");
  }
  s.meta = {{"format", "MATLAB MAT-file (libmatio)"},
            {"column", "variable " + s.name},
            {"time base", base}};
  return s;
}

}  // namespace ohmdem::post
