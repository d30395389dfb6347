// SPDX-License-Identifier: GPL-2.0-or-later
// Argument parsing for the ohmdem styles: every error names the style, the keyword and the
// expected form (LIGGGHTS' force->numeric() only says "Expected floating point parameter").
#ifndef OHMDEM_SUPPORT_ARGS_H
#define OHMDEM_SUPPORT_ARGS_H

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "error.h"

namespace ohmdem {

class StyleArgs {
 public:
  StyleArgs(LAMMPS_NS::Error *error, std::string style, int narg, char **arg, int first)
      : error_(error), style_(std::move(style)), narg_(narg), arg_(arg), pos_(first)
  {
  }

  bool done() const { return pos_ >= narg_; }
  const char *peek() const { return pos_ < narg_ ? arg_[pos_] : ""; }
  bool next_is(const char *word) const { return pos_ < narg_ && std::string(arg_[pos_]) == word; }
  bool next_is_number() const
  {
    if (pos_ >= narg_) return false;
    char *end = nullptr;
    std::strtod(arg_[pos_], &end);
    return end != arg_[pos_] && *end == '\0';
  }

  // The next word; `what` describes the expected value for the error message.
  const char *word(const std::string &keyword, const std::string &what)
  {
    if (pos_ >= narg_) fail(keyword, what, "nothing");
    return arg_[pos_++];
  }

  double number(const std::string &keyword, const std::string &what)
  {
    const char *s = word(keyword, what);
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v)) fail(keyword, what, s);
    return v;
  }
  double positive(const std::string &keyword, const std::string &what)
  {
    const double v = number(keyword, what);
    if (!(v > 0.0)) fail(keyword, what, arg_[pos_ - 1]);
    return v;
  }
  double non_negative(const std::string &keyword, const std::string &what)
  {
    const double v = number(keyword, what);
    if (!(v >= 0.0)) fail(keyword, what, arg_[pos_ - 1]);
    return v;
  }
  int integer(const std::string &keyword, const std::string &what, int lo, int hi)
  {
    const char *s = word(keyword, what);
    char *end = nullptr;
    errno = 0;
    const long v = std::strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE || v < lo || v > hi) fail(keyword, what, s);
    return static_cast<int>(v);
  }
  bool yes_no(const std::string &keyword)
  {
    const std::string s = word(keyword, "yes or no");
    if (s == "yes") return true;
    if (s == "no") return false;
    fail(keyword, "yes or no", s.c_str());
    return false;
  }

  [[noreturn]] void fail(const std::string &keyword, const std::string &what, const char *got)
  {
    const std::string msg =
        style_ + ": keyword '" + keyword + "' expects " + what + ", got '" + got + "'";
    error_->all(FLERR, msg.c_str());
    std::abort();  // error->all does not return; this keeps the compiler informed
  }
  [[noreturn]] void unknown(const char *got, const std::string &known)
  {
    const std::string msg =
        style_ + ": unknown keyword '" + got + "' (known keywords: " + known + ")";
    error_->all(FLERR, msg.c_str());
    std::abort();
  }

 private:
  LAMMPS_NS::Error *error_;
  std::string style_;
  int narg_;
  char **arg_;
  int pos_;
};

}  // namespace ohmdem

#endif
