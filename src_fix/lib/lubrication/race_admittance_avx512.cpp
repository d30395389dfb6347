// SPDX-License-Identifier: GPL-2.0-or-later
// RaceAdmittance::contacts' AVX-512 form: a race's contacts eight at a time while eight are
// left, the rest four at a time as the AVX2 form (race_lanes.h). This file alone is built for
// AVX-512F and DQ (CMakeLists.txt), with -ffp-contract=off as the other forms: the same bits.
// race_admittance_batch.cpp calls it only on a CPU that has them.
#include <cstddef>

#include "lubrication/race_admittance.h"
#include "lubrication/race_lanes.h"

namespace ohmdem::lubrication {

double contacts_avx512(const RaceAdmittance &r, const ContactBatch &in, ContactAdmittance *out,
                       std::size_t n)
{
  return RaceLanes::run<Isa::avx512>(r, in, out, n);
}

}  // namespace ohmdem::lubrication
