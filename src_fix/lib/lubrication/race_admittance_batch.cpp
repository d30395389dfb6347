// SPDX-License-Identifier: GPL-2.0-or-later
// RaceAdmittance::contacts: a race's contacts four or eight per operation (common/lanes.h), each
// lane the same operations in the same order as RaceAdmittance::contact, so each contact's record
// is that function's bit for bit (the bench's deck gives the same numbers as the scalar path,
// with any number of processes). The scalar function's branches are masks; a lane that would
// take one of its rare branches (inputs outside the inline functions' ranges, erfc below 0.5,
// the wetted circle not holding the ellipse) is redone by the scalar code, alone. A last group
// of one contact goes to the scalar code too (cheaper than four lanes); one of two or three is
// padded with a plain contact that is computed and dropped. Both races at once: their last
// contacts share a group, each lane with its race's constants. The constants are read as
// four-lane operands kept by RaceAdmittance (one load per use instead of a broadcast). The body is
// compiled three times, for SSE2, AVX2 (there with lanes.h's gathers, sign masks and blends) and
// AVX-512 (a race's contacts eight at a time while eight are left, with mask registers and
// permuted tables; the rest four at a time as AVX2's), chosen at run time: the same bits (no
// FMA: the files are built with -ffp-contract=off). The kernel itself: race_lanes.h.
#include <cstddef>

#include "lubrication/race_admittance.h"
#include "lubrication/race_lanes.h"

namespace ohmdem::lubrication {

void RaceAdmittance::splat_constants(RaceAdmittance &r)
{
  const RaceConstants four = RaceLanes::in_lanes<v4d>(r);
  const RaceConstantsOf<v8d> eight = RaceLanes::in_lanes<v8d>(r);
  __builtin_memcpy(r.splat_.data(), &four, sizeof four);
  __builtin_memcpy(r.splat8_.data(), &eight, sizeof eight);
}

namespace {

// One copy of the kernel per use and instruction set (it is inlined where it is used; the
// AVX-512 one is race_admittance_avx512.cpp's). Each returns its races' smallest film.minimum
// (RaceLanes::fold). The shared group is four lanes in every set (AVX-512's: AVX2's).
__attribute__((target("avx2"))) double contacts_avx2(const RaceAdmittance &r,
                                                     const ContactBatch &in, ContactAdmittance *out,
                                                     std::size_t n)
{
  return RaceLanes::run<Isa::avx2>(r, in, out, n);
}

double contacts_sse2(const RaceAdmittance &r, const ContactBatch &in, ContactAdmittance *out,
                     std::size_t n)
{
  return RaceLanes::run<Isa::plain>(r, in, out, n);
}

__attribute__((target("avx2"))) void mixed_avx2(const RaceAdmittance &ra, const ContactBatch &ia,
                                                ContactAdmittance *oa, std::size_t la,
                                                const RaceAdmittance &rb, const ContactBatch &ib,
                                                ContactAdmittance *ob, std::size_t lb, double &ma,
                                                double &mb)
{
  RaceLanes::mixed<Isa::avx2>(ra, ia, oa, la, rb, ib, ob, lb, ma, mb);
}

void mixed_sse2(const RaceAdmittance &ra, const ContactBatch &ia, ContactAdmittance *oa,
                std::size_t la, const RaceAdmittance &rb, const ContactBatch &ib,
                ContactAdmittance *ob, std::size_t lb, double &ma, double &mb)
{
  RaceLanes::mixed<Isa::plain>(ra, ia, oa, la, rb, ib, ob, lb, ma, mb);
}

// The set a call runs with: the asked one, or the best below it that the CPU has.
lanes::Isa isa_for(RaceAdmittance::Isa asked)
{
  static const bool avx2 = __builtin_cpu_supports("avx2");
  static const bool avx512 =
      avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  if (asked == RaceAdmittance::Isa::sse2 || !avx2) return Isa::plain;
  return asked == RaceAdmittance::Isa::best && avx512 ? Isa::avx512 : Isa::avx2;
}

using EachRace = double (*)(const RaceAdmittance &, const ContactBatch &, ContactAdmittance *,
                            std::size_t);
EachRace each_race(lanes::Isa isa)
{
  return isa == Isa::avx512 ? contacts_avx512 : isa == Isa::avx2 ? contacts_avx2 : contacts_sse2;
}

}  // namespace

const char *RaceAdmittance::best_isa()
{
  const lanes::Isa set = isa_for(Isa::best);
  return set == lanes::Isa::avx512 ? "avx512" : set == lanes::Isa::avx2 ? "avx2" : "sse2";
}

void RaceAdmittance::contacts(const ContactBatch &in, ContactAdmittance *out, Isa isa) const
{
  each_race(isa_for(isa))(*this, in, out, in.size());
}

std::array<RaceAdmittance::Minima, 2> RaceAdmittance::contacts(
    const RaceAdmittance &a, const ContactBatch &in_a, ContactAdmittance *out_a,
    const RaceAdmittance &b, const ContactBatch &in_b, ContactAdmittance *out_b, Isa isa)
{
  const lanes::Isa set = isa_for(isa);
  const EachRace each = each_race(set);
  const std::size_t na = in_a.size(), nb = in_b.size();
  const std::size_t la = RaceLanes::tail(set, na), lb = RaceLanes::tail(set, nb);
  double ma, mb;
  if (!RaceLanes::mixes(a, la, b, lb)) {
    ma = each(a, in_a, out_a, na);
    mb = each(b, in_b, out_b, nb);
  } else {
    ma = each(a, in_a, out_a, na - la);
    mb = each(b, in_b, out_b, nb - lb);
    (set == lanes::Isa::plain ? mixed_sse2 : mixed_avx2)(a, in_a, out_a, la, b, in_b, out_b, lb, ma,
                                                         mb);
  }
  // The smallest lambda is the smallest film's (RaceLanes::fold).
  return {Minima{ma, ma * a.inv_sigma_}, Minima{mb, mb * b.inv_sigma_}};
}

}  // namespace ohmdem::lubrication
