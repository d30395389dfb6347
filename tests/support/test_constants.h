// SPDX-License-Identifier: GPL-2.0-or-later
// Constants the tests share (the production code has its own in src_fix/lib/common/constants.h;
// tests keep theirs so that a reference value never comes from the code under test).
#ifndef OHMDEM_TESTS_SUPPORT_TEST_CONSTANTS_H
#define OHMDEM_TESTS_SUPPORT_TEST_CONSTANTS_H

namespace ohmdem::test {

inline constexpr double kPi = 3.14159265358979323846264338327950288;

}  // namespace ohmdem::test

#endif
