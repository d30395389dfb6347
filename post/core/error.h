// SPDX-License-Identifier: GPL-2.0-or-later
// Errors of the post-processing library: one exception type, caught by the command line,
// which prints "ERROR: <message>" on stderr and exits non-zero.
#ifndef OHMDEM_POST_ERROR_H
#define OHMDEM_POST_ERROR_H

#include <stdexcept>
#include <string>

namespace ohmdem::post {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ohmdem::post

#endif
