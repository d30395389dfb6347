// SPDX-License-Identifier: GPL-2.0-or-later
// Constants of the post-processing library, defined once (std::numbers is C++20).
#ifndef OHMDEM_POST_CONSTANTS_H
#define OHMDEM_POST_CONSTANTS_H

namespace ohmdem::post {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace ohmdem::post

#endif
