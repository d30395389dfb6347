// SPDX-License-Identifier: GPL-2.0-or-later
// The one home of the mathematical constants of the engine side. kPi is the double nearest
// to pi, the same value as POSIX M_PI (which the C++ standard does not promise).
#ifndef OHMDEM_CONSTANTS_H
#define OHMDEM_CONSTANTS_H

namespace ohmdem {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;  // one degree in radians

}  // namespace ohmdem

#endif
