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

// The last contacts of two races in one group: la of race a (from its contact na - la), then
// lb of race b, each lane with its race's constants (la, lb >= 1, la + lb <= 4, the same
// permittivity form); padding as race a's. Each race's films into its minima, from the
// records.
template <Isa kIsa>
OHMDEM_LANES_INLINE void RaceLanes::mixed(const RaceAdmittance &ra, const ContactBatch &ia,
                                          ContactAdmittance *oa, std::size_t la,
                                          const RaceAdmittance &rb, const ContactBatch &ib,
                                          ContactAdmittance *ob, std::size_t lb, double &ma,
                                          double &mb)
{
  const std::size_t na = ia.size(), nb = ib.size();
  RaceAdmittance::Blended &blended = ra.blended_;
  if (blended.partner != rb.serial_ || blended.la != la || blended.lb != lb) {
    blend(constants(ra), constants(rb), ra.rational_, la, lb, blended.splat.data());
    blended.partner = rb.serial_;
    blended.la = la;
    blended.lb = lb;
  }
  const RaceConstants &k = *reinterpret_cast<const RaceConstants *>(blended.splat.data());
  ContactAdmittance *lanes[kLanes];
  Group<v4d> grp{&k, {&ra, &ra, &ra, &ra}, nullptr, lanes};
  v4d fn = splat<v4d>(1.0), speed = splat<v4d>(1.0), g_dry = splat<v4d>(0.0),
      recess = splat<v4d>(0.0);
  ContactAdmittance dropped;  // the padding lanes' records
  for (int l = 0; l < kLanes; ++l) {
    const bool in_a = static_cast<std::size_t>(l) < la,
               in_b = !in_a && static_cast<std::size_t>(l) < la + lb;
    const ContactBatch &in = in_b ? ib : ia;
    const std::size_t at = in_b ? nb - lb + (l - la) : na - la + l;
    grp.race[l] = in_b ? &rb : &ra;
    lanes[l] = in_a ? oa + at : in_b ? ob + at : &dropped;
    if (!in_a && !in_b) continue;
    fn[l] = in.fn()[at];
    speed[l] = in.speed()[at];
    g_dry[l] = in.g_dry()[at];
    recess[l] = in.recess()[at];
  }
  four<kIsa>(grp, ra.rational_, fn, speed, g_dry, recess, static_cast<int>(la + lb),
             static_cast<v4d *>(nullptr));
  for (std::size_t l = 0; l < la; ++l) fold(ma, oa[na - la + l]);
  for (std::size_t l = 0; l < lb; ++l) fold(mb, ob[nb - lb + l]);
}

// The constants of a group of la lanes of race a, then lb of race b, lane by lane into `to`
// (RaceConstants' layout; wt and dt only for the eight divisions' form: never read in the
// one-fraction form). RaceConstants is 56 vectors in a row (static_assert above): its bytes
// taken 32 at a time. Plain code (either instruction set's caller): rarely run.
void RaceLanes::blend(const RaceConstants &ka, const RaceConstants &kb, bool rational,
                      std::size_t la, std::size_t lb, double *to)
{
  v4i from_b = splat<v4d>(0.0) > 1.0;  // no lane
  for (std::size_t l = la; l < la + lb; ++l) from_b[l] = -1;
  const char *pa = reinterpret_cast<const char *>(&ka), *pb = reinterpret_cast<const char *>(&kb);
  char *pk = reinterpret_cast<char *>(to);
  const std::size_t fields =
      rational ? offsetof(RaceConstants, wt) / sizeof(v4d) : sizeof(RaceConstants) / sizeof(v4d);
  for (std::size_t f = 0; f < fields; ++f) {
    v4d va, vb;
    __builtin_memcpy(&va, pa + f * sizeof(v4d), sizeof va);
    __builtin_memcpy(&vb, pb + f * sizeof(v4d), sizeof vb);
    const v4d v = select(from_b, vb, va);
    __builtin_memcpy(pk + f * sizeof(v4d), &v, sizeof v);
  }
}

// The race's constants, each in every lane of V.
template <class V>
RaceConstantsOf<V> RaceLanes::in_lanes(const RaceAdmittance &r)
{
  RaceConstantsOf<V> k;
  k.a_coef = splat<V>(r.in_.a_coef);
  k.b_coef = splat<V>(r.in_.b_coef);
  k.central = splat<V>(r.central_);
  k.ell_central = splat<V>(r.ell_central_);
  k.minimum = splat<V>(r.minimum_);
  k.ell_minimum = splat<V>(r.ell_minimum_);
  k.inv_sigma = splat<V>(r.inv_sigma_);
  k.area_coef = splat<V>(r.area_coef_);
  k.inv_resistivity = splat<V>(r.inv_resistivity_);
  k.q0_coef = splat<V>(r.q0_coef_);
  k.sigma = splat<V>(r.in_.sigma);
  k.r_wet = splat<V>(r.in_.r_wet);
  k.p = splat<V>(r.p_);
  k.q = splat<V>(r.q_);
  k.r2 = splat<V>(r.r2_);
  k.sp_coef = splat<V>(r.sp_coef_);
  k.sq_coef = splat<V>(r.sq_coef_);
  k.hertz_s = splat<V>(r.hertz_s_);
  k.hertz_y = splat<V>(r.hertz_y_);
  k.scale = splat<V>(r.scale_);
  k.eps_const = splat<V>(r.eps_const_);
  k.eps_pole = splat<V>(r.eps_pole_);
  k.ga = splat<V>(r.ga_);
  for (int i = 0; i < 8; ++i) {
    k.pc[i] = splat<V>(r.pc_[i]);
    k.wt[i] = splat<V>(r.wt_[i]);
    k.dt[i] = splat<V>(r.dt_[i]);
  }
  for (int i = 0; i < 9; ++i) k.qc[i] = splat<V>(r.qc_[i]);
  return k;
}

// The contacts a race of n leaves to the shared group: its last n % 4 (AVX-512: its last
// n % 8 of 1 to 4 but four, as run() leaves them).
std::size_t RaceLanes::tail(Isa isa, std::size_t n)
{
  const std::size_t r = isa == Isa::avx512 ? n % 8 : n % kLanes;
  return r < kLanes ? r : 0;
}
// Whether two races' last contacts go in one group: both have some, they fit, and the races'
// permittivity is in the same form.
bool RaceLanes::mixes(const RaceAdmittance &ra, std::size_t la, const RaceAdmittance &rb,
                      std::size_t lb)
{
  return la > 0 && lb > 0 && la + lb <= kLanes && ra.rational_ == rb.rational_;
}

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
