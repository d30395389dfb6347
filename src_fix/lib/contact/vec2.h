// SPDX-License-Identifier: GPL-2.0-or-later
// A vector in the bearing plane (x, y), shared by the contact kernels.
#ifndef OHMDEM_VEC2_H
#define OHMDEM_VEC2_H

namespace ohmdem {

struct Vec2 {
  double x = 0;
  double y = 0;
};

}  // namespace ohmdem

#endif
