// SPDX-License-Identifier: GPL-2.0-or-later
// Global restart data of an ohmdem fix, the LAMMPS convention for Fix::write_restart: process
// 0 writes the size in bytes, then the values; Fix::restart(buf) gets the values back.
#ifndef OHMDEM_STYLE_GLOBAL_RESTART_H
#define OHMDEM_STYLE_GLOBAL_RESTART_H

#include <cstddef>
#include <cstdio>

namespace ohmdem {

template <std::size_t N>
inline void write_global_restart(int me, FILE *fp, const double (&list)[N])
{
  if (me != 0) return;
  const int size = static_cast<int>(N * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), N, fp);
}

}  // namespace ohmdem

#endif
